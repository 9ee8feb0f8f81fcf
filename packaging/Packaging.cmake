# Radiant installed like any Debian program (issue #19): `cmake --install` lays out the program, its
# built-in scenes, a desktop entry and icon, a man page and bash completion; `cpack -G DEB` packs
# that tree as radiant_<version>_amd64.deb. Included at the end of the top CMakeLists.txt.

# The layout is fixed: the program finds its scenes at ../share/radiant/assets beside itself
# (radiometry/scene/AssetDirectory.cpp), so bin/ and share/ must be siblings whatever the prefix.
set(RADIANT_INSTALL_BINDIR bin)
set(RADIANT_INSTALL_DATADIR share)
# Directories the package creates are 0755 whatever the builder's umask (dpkg keeps what it is given).
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

# The man page and the bash completion are written from the built program's --help, so they list
# exactly the subcommands and options it parses (packaging/GenerateFromHelp.cmake).
set(RADIANT_MAN_PAGE ${CMAKE_CURRENT_BINARY_DIR}/packaging/radiant.1)
set(RADIANT_BASH_COMPLETION ${CMAKE_CURRENT_BINARY_DIR}/packaging/radiant.bash-completion)
add_custom_command(
  OUTPUT ${RADIANT_MAN_PAGE} ${RADIANT_BASH_COMPLETION}
  COMMAND ${CMAKE_COMMAND} -DRADIANT=$<TARGET_FILE:radiant> -DMAN_PAGE=${RADIANT_MAN_PAGE}
          -DCOMPLETION=${RADIANT_BASH_COMPLETION} -P ${CMAKE_CURRENT_SOURCE_DIR}/packaging/GenerateFromHelp.cmake
  DEPENDS radiant ${CMAKE_CURRENT_SOURCE_DIR}/packaging/GenerateFromHelp.cmake
  COMMENT "Writing the man page and bash completion from radiant --help"
  VERBATIM)
add_custom_target(radiant_help_documents ALL DEPENDS ${RADIANT_MAN_PAGE} ${RADIANT_BASH_COMPLETION})

install(TARGETS radiant RUNTIME DESTINATION ${RADIANT_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/assets/ DESTINATION ${RADIANT_INSTALL_DATADIR}/radiant/assets)
install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/packaging/radiant.desktop DESTINATION ${RADIANT_INSTALL_DATADIR}/applications)
install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/packaging/radiant.svg
        DESTINATION ${RADIANT_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${RADIANT_MAN_PAGE} DESTINATION ${RADIANT_INSTALL_DATADIR}/man/man1)
install(FILES ${RADIANT_BASH_COMPLETION} DESTINATION ${RADIANT_INSTALL_DATADIR}/bash-completion/completions
        RENAME radiant)

# The Debian package. Its version is project(VERSION), which `radiant --version` prints too; its
# dependencies are read from the program's shared libraries by dpkg-shlibdeps (package dpkg-dev),
# plus what is loaded at run time, which no ELF header names: libGL, which libepoxy and GLFW open for
# the window's GLX context, and Mesa's drivers behind libGL and libEGL (without them a machine with
# no GPU driver has no llvmpipe, and neither the lab nor `radiant render` can draw).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME radiant)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Radiant")
set(CPACK_PACKAGE_CONTACT "Radiant maintainers <maintainers@users.noreply.h-seed-204480ad.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "interactive lab for radiometry and radiosity")
set(CPACK_PACKAGE_DESCRIPTION "Radiant shows what light does, on a projector or a student's laptop: step
through a radiosity solve (Jacobi, Gauss-Seidel, progressive, hierarchical and importance-driven),
click any point to read its radiance, irradiance and the solid angle of what it sees, and explore
hemisphere integrals. Opens glTF scenes; solve, probe, reference and render run without a window.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgl1, libgl1-mesa-dri, libegl-mesa0")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)

# No path of this machine in the program (issue #19): a scan of its printable strings, like
# `strings radiant`. radiant_make_assets, which names the source tree on purpose, must be caught by
# the same scan, so the test cannot pass by reading nothing.
# Only where the package is made from: sanitizer builds (never installed) keep debug information whose
# compile directory names their build folder.
if(RADIANT_BUILD_TESTS AND NOT RADIANT_SANITIZE)
  add_test(NAME no_build_paths COMMAND ${CMAKE_COMMAND} -DBINARY=$<TARGET_FILE:radiant>
           -DCONTROL=$<TARGET_FILE:radiant_make_assets> -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}
           -DBINARY_DIR=${CMAKE_CURRENT_BINARY_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/packaging/CheckNoBuildPaths.cmake)
endif()
