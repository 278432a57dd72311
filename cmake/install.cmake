# SPDX-License-Identifier: MIT
# What `cmake --install` puts where (GNU directories, docs/install.md):
#   bin/sandglass                                  the program
#   libexec/sandglass/sandglass-import             the model importer it starts (docs/shapes.md)
#   share/sandglass/shaders, share/sandglass/models GLSL, bundled models and draft images
#   share/applications, share/icons, share/metainfo, share/mime/packages   desktop integration
#   share/doc/sandglass                            README, LICENSE, CHANGELOG
#   include/sandcore, lib/libsandcore.a, lib/cmake/sandcore   the library as a package (sandcore/)
# The program finds its data relative to bin/ (scene/data_paths.hpp), so the tree can be moved.
install(TARGETS sandglass RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(TARGETS sandglass-import RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/sandglass COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sandglass/shaders COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/ DESTINATION ${CMAKE_INSTALL_DATADIR}/sandglass/models COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/desktop/sandglass.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications
        COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/desktop/sandglass.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps
        COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/desktop/sandglass.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo
        COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/desktop/sandglass-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
        RENAME sandglass.xml COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)

# cpack -G DEB: two packages, `sandglass` (the program) and `sandcore-dev` (the library, its
# headers and CMake package). dpkg-shlibdeps reads the program's shared libraries and names the
# Debian packages that hold them as dependencies.
set(SANDGLASS_PACKAGE_CONTACT "sandglass maintainers <maintainers@sandglass.invalid>"
    CACHE STRING "Maintainer named in the Debian packages")
set(CPACK_PACKAGE_NAME sandglass)
set(CPACK_PACKAGE_VENDOR "the sandglass authors")
set(CPACK_PACKAGE_CONTACT "${SANDGLASS_PACKAGE_CONTACT}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGE_INSTALL_DIRECTORY sandglass)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME sandglass)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# The font and the file dialog are read or started at run time, not linked.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "fonts-dejavu-core")
# zenity is only suggested: as a recommendation apt would also bring its GTK and WebKit stack.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "zenity")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME sandcore-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
    "Real-time 3D sand: an hourglass of any 3D model, sand sculptures that collapse, and painting with pouring sand")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION "sandcore, the sand simulation library of sandglass (C++20, static, CMake package)")
include(CPack)
