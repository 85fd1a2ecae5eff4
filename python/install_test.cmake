# ctest python_install: `cmake --install` into a fresh prefix, then Python imports plascap from
# there (not from the build tree) and computes one capacity.
# -D BUILD_DIR=... -D PREFIX=... -D PACKAGE_DIR=<relative to the prefix> -D PYTHON=...
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}" RESULT_VARIABLE installed OUTPUT_QUIET)
if(NOT installed EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${installed})")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${PREFIX}/${PACKAGE_DIR}"
          "${PYTHON}" -c "import plascap, sys; assert plascap.__file__.startswith(sys.argv[1]), plascap.__file__; print(plascap.Section.rectangle(0.2, 0.1, fy=1e5).capacities().N)" "${PREFIX}"
  WORKING_DIRECTORY "${PREFIX}" RESULT_VARIABLE imported OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT imported EQUAL 0)
  message(FATAL_ERROR "importing the installed plascap failed: ${err}")
endif()
if(NOT out MATCHES "^2000")
  message(FATAL_ERROR "the installed plascap computed N = ${out} for a 0.2 x 0.1 m rectangle at 1e5 Pa (2000 N)")
endif()
