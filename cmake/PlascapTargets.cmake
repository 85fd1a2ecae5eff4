# plascap_warnings(target): the warning set every plascap target compiles clean with.
function(plascap_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()

# plascap_library(target EXPORT_NAME name SOURCES ...): a plascap library with its public headers in
# include/, the project's warnings, the plascap:: alias, and install + export rules.
function(plascap_library target)
  cmake_parse_arguments(ARG "" "EXPORT_NAME" "SOURCES" ${ARGN})
  add_library(${target} ${ARG_SOURCES})
  add_library(plascap::${ARG_EXPORT_NAME} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${ARG_EXPORT_NAME} OUTPUT_NAME ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  plascap_warnings(${target})
  # A shared library's calls between its own exported functions go through the PLT and cannot be
  # inlined, because by default the ELF rules let another library interpose them (GCC manual,
  # -fsemantic-interposition). plascap does not support interposing its functions, so let the
  # compiler bind them locally: the ODE joint's step calls a dozen small ones (docs/adapters.md "Cost").
  target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  install(TARGETS ${target} EXPORT plascapTargets)
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
