# `cmake --install` (and `make install PREFIX=...`): the `locus` executable, the OpenImageIO
# and HTTP modules beside it in lib/locus (found from the executable's path, so a moved tree still
# works: render/image_output.cpp), the library headers under include/locus, CMake package files
# for find_package(locus) with the targets locus::algebra, locus::implicit, locus::render, the
# docs and the example scenes and parametrizations.
include(CMakePackageConfigHelpers)

set_target_properties(locus_algebra PROPERTIES EXPORT_NAME algebra)
set_target_properties(locus_implicit PROPERTIES EXPORT_NAME implicit)
set_target_properties(locus_render PROPERTIES EXPORT_NAME render)
set(locus_exported_targets locus_algebra locus_implicit locus_render locus_flint locus_warnings)
if(LOCUS_SANITIZE)
    list(APPEND locus_exported_targets locus_image_file)  # linked in, not a module (render/)
else()
    install(TARGETS locus_image_file locus_http LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/locus)
endif()
install(TARGETS locus RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${locus_exported_targets} EXPORT locusTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY algebra implicit render
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/locus
    FILES_MATCHING PATTERN "*.h")
install(EXPORT locusTargets NAMESPACE locus::
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/locus)
configure_package_config_file(cmake/locusConfig.cmake.in
    ${PROJECT_BINARY_DIR}/locusConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/locus)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/locusConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/locusConfig.cmake ${PROJECT_BINARY_DIR}/locusConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/locus)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/locus/scenes)
install(DIRECTORY bench/data/implicit/ DESTINATION ${CMAKE_INSTALL_DATADIR}/locus/examples
    FILES_MATCHING PATTERN "*.param")
