# Installing PKM Studio where Debian expects it, and its Debian package.
#
#   cmake --install build --prefix /usr          the files below, under the prefix
#   cd build && cpack -G DEB                      pkm-studio_<version>_<arch>.deb
#
# The programs go to bin/, the drawing half of the command line to libexec/pkm-studio/ (pkm
# finds it there, app/cli/main.cpp), the Python module to lib/python3/dist-packages/
# (python/CMakeLists.txt), and the rest to share/: presets and translations under
# share/pkm-studio/, the menu entry, icon, MIME type, AppStream metadata and manual pages
# where the desktop and man look for them.
include(GNUInstallDirs)
# Debian names the documentation folder after the package, not the CMake project.
set(CMAKE_INSTALL_DOCDIR ${CMAKE_INSTALL_DATAROOTDIR}/doc/pkm-studio)

install(TARGETS pkm pkm-studio RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS pkm-draw RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/pkm-studio)

set(PKM_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/pkm-studio)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/presets/ DESTINATION ${PKM_SHARE_DIR}/presets
    FILES_MATCHING PATTERN "*.pkm.json")
install(FILES ${PKM_TRANSLATION_QM} ${PKM_ENGLISH_QM} DESTINATION ${PKM_SHARE_DIR}/translations)

# The desktop's files. The id is reverse-DNS, as AppStream asks; the icon keeps its name.
set(PKM_APP_ID org.pkmstudio.PKMStudio)
string(TIMESTAMP PKM_RELEASE_DATE "%Y-%m-%d" UTC)
configure_file(${PROJECT_SOURCE_DIR}/resources/${PKM_APP_ID}.metainfo.xml
    ${PROJECT_BINARY_DIR}/share/${PKM_APP_ID}.metainfo.xml @ONLY)
install(FILES ${PROJECT_SOURCE_DIR}/resources/${PKM_APP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_BINARY_DIR}/share/${PKM_APP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/pkm-studio.svg
    DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/resources/pkm-studio-mime.xml
    DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages RENAME pkm-studio.xml)

# Manual pages, made from the programs' own --help (and each pkm COMMAND --help) by
# cmake/manpage.py, so that they never say anything the programs do not; hand-written
# sections (examples, files, see also) come from resources/man/*.sections.
if(NOT PKM_PYTHON_EXECUTABLE)
    find_package(Python3 REQUIRED COMPONENTS Interpreter)
    set(PKM_PYTHON_EXECUTABLE ${Python3_EXECUTABLE})
endif()
set(PKM_MAN_DIR ${PROJECT_BINARY_DIR}/man)
function(pkm_manpage target name summary)
    set(page ${PKM_MAN_DIR}/${name}.1)
    set(sections ${PROJECT_SOURCE_DIR}/resources/man/${name}.1.sections)
    add_custom_command(OUTPUT ${page}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${PKM_MAN_DIR}
        COMMAND ${PKM_PYTHON_EXECUTABLE} ${PROJECT_SOURCE_DIR}/cmake/manpage.py --program $<TARGET_FILE:${target}>
            --name ${name} --summary ${summary} --version ${PROJECT_VERSION} --sections ${sections} ${ARGN} -o ${page}
        DEPENDS ${target} ${sections} ${PROJECT_SOURCE_DIR}/cmake/manpage.py
        COMMENT "Manual page ${name}.1 from ${name} --help" VERBATIM)
    install(FILES ${page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
    set_property(GLOBAL APPEND PROPERTY PKM_MANPAGES ${page})
endfunction()
pkm_manpage(pkm pkm "analyse parallel-kinematic mechanisms from the command line" --commands)
pkm_manpage(pkm-studio pkm-studio "design, analyse and teach parallel-kinematic mechanisms")
get_property(PKM_MANPAGES GLOBAL PROPERTY PKM_MANPAGES)
add_custom_target(pkm_manpages ALL DEPENDS ${PKM_MANPAGES})

install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/docs/cli.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)
install(FILES ${PROJECT_SOURCE_DIR}/examples/plot_map.py DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# The Debian package: its library dependencies found by dpkg-shlibdeps from the installed
# programs and module; Python and NumPy named, the module being built for this python3.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pkm-studio)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "PKM Studio developers <pkm-studio@pkmstudio.org>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(PKM_PYTHON_DEPENDS)
    set(CPACK_DEBIAN_PACKAGE_DEPENDS "${PKM_PYTHON_DEPENDS}")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-matplotlib, fonts-dejavu-core")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "design, analysis and teaching of parallel-kinematic mechanisms")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "design, analysis and teaching of parallel-kinematic mechanisms
 PKM Studio models the active П-joint, MOMA, the O-X glide, the planar four-bar,
 the five-bar and planar parallel mechanisms built from a library of legs: their
 kinematics with every assembly mode, Jacobians, singularity classes, workspace and
 capability maps, in a desktop application for designers and classrooms, a command
 line (pkm) and a Python module (pkmstudio).")
include(CPack)

# The installed files work from where they are installed (tests/install/check-install.sh).
if(PKM_BUILD_TESTS)
    add_test(NAME install_layout
        COMMAND ${PROJECT_SOURCE_DIR}/tests/install/check-install.sh ${PROJECT_BINARY_DIR} ${PROJECT_BINARY_DIR}/install-check)
    set_tests_properties(install_layout PROPERTIES TIMEOUT 300)
endif()
