# Script mode (cmake -P): install plascap from PLASCAP_BUILD_DIR into WORK_DIR/prefix, configure
# and build the consumer in CONSUMER_SOURCE_DIR against it (with the Bullet adapter when
# PLASCAP_EXPECT_BULLET), run it. Any failure fails the test.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install ${PLASCAP_BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/plascap-consumer)
if(EXISTS ${WORK_DIR}/build/plascap-consumer-bullet)
  run(${WORK_DIR}/build/plascap-consumer-bullet)
elseif(PLASCAP_EXPECT_BULLET)
  message(FATAL_ERROR "the installed plascap has its Bullet adapter, but the consumer did not build against it")
endif()
