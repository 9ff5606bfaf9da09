# fx_install_package(<target>)
#
# The install and export rules every package of the effect modules shares (the contracts, the
# kit and the modules built on it): the library <target>, the headers under the calling
# directory's include/, and
# a CMake package <target> (<target>Targets.cmake in the <target>:: namespace, the config from
# the calling directory's cmake/<target>Config.cmake.in, a version file, same-minor
# compatible), so a host can find_package(<target> CONFIG).
include_guard(GLOBAL)

function(fx_install_package target)
  include(GNUInstallDirs)
  include(CMakePackageConfigHelpers)
  set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/${target})
  install(TARGETS ${target} EXPORT ${target}Targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT ${target}Targets NAMESPACE ${target}:: DESTINATION ${config_dir})
  configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/${target}Config.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/${target}Config.cmake INSTALL_DESTINATION ${config_dir})
  write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/${target}ConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${target}Config.cmake
                ${CMAKE_CURRENT_BINARY_DIR}/${target}ConfigVersion.cmake
          DESTINATION ${config_dir})
endfunction()
