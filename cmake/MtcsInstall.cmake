# `cmake --install`: besides the programs, the library for other programs (as Manifold ships
# its own): each module's static library, the public headers (include/mtcs, without the CLI's),
# and a CMake package, find_package(mtcs) -> mtcs::eval, mtcs::run, ... The command line (cli)
# and the benchmarks are programs, not part of the library.
include(CMakePackageConfigHelpers)
set(MTCS_LIBRARY_MODULES geometry io mesh voxel thermal mold eval opt store run)
foreach(module ${MTCS_LIBRARY_MODULES})
  set_target_properties(mtcs_${module} PROPERTIES EXPORT_NAME ${module})
  install(TARGETS mtcs_${module} EXPORT mtcsTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/mtcs DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN cli EXCLUDE)
install(EXPORT mtcsTargets NAMESPACE mtcs:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mtcs)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/mtcsConfig.cmake.in ${PROJECT_BINARY_DIR}/mtcsConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mtcs)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mtcsConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mtcsConfig.cmake ${PROJECT_BINARY_DIR}/mtcsConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mtcs)
