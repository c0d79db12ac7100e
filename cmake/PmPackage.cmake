# cmake --install: libraries, headers, programs, shipped data and a CMake package config,
# so that a ViSP program can do find_package(visp-photomodel) and link pm::core, pm::sim, ...
include(CMakePackageConfigHelpers)
set(PM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/visp-photomodel)
install(EXPORT visp-photomodelTargets NAMESPACE pm:: DESTINATION ${PM_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/visp-photomodelConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/visp-photomodelConfig.cmake INSTALL_DESTINATION ${PM_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/visp-photomodelConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/visp-photomodelConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/visp-photomodelConfigVersion.cmake
        DESTINATION ${PM_CMAKE_DIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/visp-photomodel)
