# Debian package: `cpack -G DEB` in the build folder makes camwb_<version>_<arch>.deb.
set(CPACK_PACKAGE_NAME camwb)
set(CPACK_PACKAGE_VENDOR "CAM Workbench developers")
set(CPACK_PACKAGE_CONTACT "CAM Workbench developers <camwb@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "CAM and post-processor workbench (OpenCASCADE, Qt6)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
# The binaries go in stripped (about 5 MB installed instead of 133 MB); the build folder keeps the
# unstripped ones for gdb. tests/package checks it.
set(CPACK_STRIP_FILES TRUE)

install(FILES ${PROJECT_SOURCE_DIR}/packaging/camwb.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/camwb.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
# Post scripts only: their golden tests (posts/<id>/tests/) stay in the source tree.
file(GLOB post_scripts CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/posts/*.js)
install(FILES ${post_scripts} DESTINATION ${CMAKE_INSTALL_DATADIR}/camwb/posts)
# Code several posts share, which they include("name") from posts/include/.
file(GLOB post_includes CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/posts/include/*.js)
install(FILES ${post_includes} DESTINATION ${CMAKE_INSTALL_DATADIR}/camwb/posts/include)
# NC code a post copies into its output with readPostFile(): the lathe post's groove subprograms.
file(GLOB post_groove_subprograms CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/posts/sinumerik840d-turn/groove/*.SPF)
if(post_groove_subprograms)
  install(FILES ${post_groove_subprograms} DESTINATION ${CMAKE_INSTALL_DATADIR}/camwb/posts/sinumerik840d-turn/groove)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/machines/ DESTINATION ${CMAKE_INSTALL_DATADIR}/camwb/machines
        FILES_MATCHING PATTERN "*.json")
install(FILES ${PROJECT_SOURCE_DIR}/resources/tools/default.camwb-tools.json DESTINATION ${CMAKE_INSTALL_DATADIR}/camwb/tools)
install(FILES ${PROJECT_SOURCE_DIR}/resources/examples/example-block.camwb
              ${PROJECT_SOURCE_DIR}/resources/examples/example-block.step
        DESTINATION ${CMAKE_INSTALL_DATADIR}/camwb/examples)

include(CPack)
