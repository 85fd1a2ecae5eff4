# Runs one engine benchmark briefly (cmake -DBENCH=<binary> -DFILTER=<regex> -P smoke.cmake) and
# fails unless it exits 0 and every benchmark it ran reports a finite, positive vs_rigid.
execute_process(COMMAND ${BENCH} --benchmark_filter=${FILTER} --benchmark_min_time=0.01 --benchmark_format=json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${BENCH} exited with ${rc}: ${err}")
endif()
string(REGEX MATCHALL "\"run_name\": " runs "${out}")
string(REGEX MATCHALL "\"vs_rigid\": [0-9][^,\n]*" ratios "${out}")
list(LENGTH runs run_count)
list(LENGTH ratios ratio_count)
if(run_count EQUAL 0 OR NOT run_count EQUAL ratio_count)
  message(FATAL_ERROR "${BENCH}: ${run_count} benchmarks ran, ${ratio_count} reported a finite vs_rigid:\n${out}")
endif()
message(STATUS "${BENCH}: ${run_count} benchmarks, each with a vs_rigid: ${ratios}")
