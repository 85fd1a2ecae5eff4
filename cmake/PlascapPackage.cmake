# Install rules and the exported CMake package: find_package(plascap) gives plascap::sections,
# plascap::materials, plascap::common, plascap::adapters_common, plascap::section_joints, and plascap::bullet and plascap::ode
# when those adapters were built (test with if(TARGET plascap::bullet)).
include(CMakePackageConfigHelpers)

set(PLASCAP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/plascap)
install(EXPORT plascapTargets NAMESPACE plascap:: DESTINATION ${PLASCAP_CMAKE_DIR})
configure_package_config_file(cmake/plascapConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/plascapConfig.cmake INSTALL_DESTINATION ${PLASCAP_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/plascapConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/plascapConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/plascapConfigVersion.cmake
        DESTINATION ${PLASCAP_CMAKE_DIR})
