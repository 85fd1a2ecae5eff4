# plascap_warnings(target): the warning set every plascap target compiles clean with.
function(plascap_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
