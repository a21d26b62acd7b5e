# The Debian packages (included from platform/CMakeLists.txt). `cpack -G DEB` in a build directory
# makes two. noneuclid packs what `cmake --install` installs but the library (the program, the
# board files, the unit, the manual page, the documents) with what only a system package does:
# the user noneuclid, the state directory, the board override as a conffile, GPIO chips for the
# group gpio, and the maintainer scripts. noneuclid-dev packs the library (the install component
# dev, src/library.cmake: headers, static libraries, libnoneuclid.so where built, the CMake
# package; docs/library.md). platform/debian/build-packages makes them for amd64, arm64 and
# armhf from the presets of the same names, which install under /usr: the paths compiled into
# the program and the unit are the package's.
#
# Depends come from the binary (dpkg-shlibdeps: libc, libstdc++, and libgpiod, libpng, zlib,
# X11 and libasound where linked shared, as in the amd64 build; the cross builds link libgpiod
# statically and have no PNG, zlib, X11 or sound), plus systemd, whose sysusers and tmpfiles the
# postinst runs.

# Debian's name for the architecture built for.
set(noneuclid_deb_arch_aarch64 arm64)
set(noneuclid_deb_arch_arm armhf)
set(noneuclid_deb_arch_x86_64 amd64)
if(CMAKE_CROSSCOMPILING)
    set(NONEUCLID_DEB_ARCH "${noneuclid_deb_arch_${CMAKE_SYSTEM_PROCESSOR}}")
else()
    execute_process(COMMAND dpkg --print-architecture OUTPUT_VARIABLE NONEUCLID_DEB_ARCH
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
endif()
if(NOT NONEUCLID_DEB_ARCH)
    return()  # not a Debian architecture (or not a Debian machine): no package
endif()

set(noneuclid_pkg ${CMAKE_CURRENT_LIST_DIR})
set(noneuclid_pkg_out ${PROJECT_BINARY_DIR}/package)

# The system files, in the package only (component deb, not part of a plain `cmake --install`):
# systemd reads them from /usr/lib only, and a build installed under /usr/local makes its user by
# hand (docs/kiosk.md).
install(FILES ${noneuclid_pkg}/noneuclid.sysusers DESTINATION lib/sysusers.d RENAME noneuclid.conf
        COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${noneuclid_pkg}/noneuclid.tmpfiles DESTINATION lib/tmpfiles.d RENAME noneuclid.conf
        COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${noneuclid_pkg}/60-noneuclid-gpio.rules DESTINATION lib/udev/rules.d COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${noneuclid_pkg}/board-override.toml DESTINATION ${CMAKE_INSTALL_FULL_SYSCONFDIR}/noneuclid
        RENAME board.toml COMPONENT deb EXCLUDE_FROM_ALL)

# /usr/share/doc/noneuclid/copyright and changelog.gz (a native package's changelog: one entry,
# this version, dated like the manual page).
if(NOT NONEUCLID_SOURCE_DATE_EPOCH)
    string(TIMESTAMP NONEUCLID_SOURCE_DATE_EPOCH "%s" UTC)
endif()
execute_process(COMMAND date -u -R -d @${NONEUCLID_SOURCE_DATE_EPOCH} OUTPUT_VARIABLE NONEUCLID_DEB_DATE
                OUTPUT_STRIP_TRAILING_WHITESPACE)
execute_process(COMMAND git -C ${PROJECT_SOURCE_DIR} rev-parse --short HEAD OUTPUT_VARIABLE NONEUCLID_GIT_COMMIT
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
# (The changelog's line stays within lintian's 80 columns either way.)
if(NONEUCLID_GIT_COMMIT)
    set(NONEUCLID_GIT_COMMIT "commit ${NONEUCLID_GIT_COMMIT}")
else()
    set(NONEUCLID_GIT_COMMIT "a tree outside git")
endif()
set(NONEUCLID_DEB_MAINTAINER "noneuclid maintainers <maintainers@users.noreply.h-seed-35e1c005.example>"
    CACHE STRING "The Debian package's Maintainer field")
configure_file(${noneuclid_pkg}/changelog.in ${noneuclid_pkg_out}/changelog @ONLY)
add_custom_command(OUTPUT ${noneuclid_pkg_out}/changelog.gz
    COMMAND gzip -9nkf ${noneuclid_pkg_out}/changelog
    DEPENDS ${noneuclid_pkg_out}/changelog VERBATIM)
add_custom_target(noneuclid_deb_changelog ALL DEPENDS ${noneuclid_pkg_out}/changelog.gz)
install(FILES ${noneuclid_pkg}/copyright ${noneuclid_pkg_out}/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR}
        COMPONENT deb EXCLUDE_FROM_ALL)
# noneuclid-dev's own (it does not depend on noneuclid: a program built with it needs only libc).
install(FILES ${noneuclid_pkg}/copyright ${noneuclid_pkg_out}/changelog.gz
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/noneuclid-dev COMPONENT devdeb EXCLUDE_FROM_ALL)

# The maintainer scripts and the conffile list, with the unit's and files' names filled in.
foreach(script postinst prerm postrm)
    configure_file(${noneuclid_pkg}/${script} ${noneuclid_pkg_out}/control/${script} @ONLY
                   FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
endforeach()
file(WRITE ${noneuclid_pkg_out}/control/conffiles "${CMAKE_INSTALL_FULL_SYSCONFDIR}/noneuclid/board.toml\n")

# Two packages of four components: noneuclid of the default one (the program, ...) and deb;
# noneuclid-dev of dev (the library) and devdeb. What is not said per package is both's.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME noneuclid)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DIRECTORY ${noneuclid_pkg_out})
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_SET_DESTDIR ON)  # the files under /etc keep their absolute path
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ONE_PER_GROUP)
set(CPACK_COMPONENTS_ALL Unspecified deb dev devdeb)
set(CPACK_COMPONENT_UNSPECIFIED_GROUP runtime)
set(CPACK_COMPONENT_DEB_GROUP runtime)
set(CPACK_COMPONENT_DEV_GROUP dev)
set(CPACK_COMPONENT_DEVDEB_GROUP dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME noneuclid)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME noneuclid-dev)
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${NONEUCLID_DEB_ARCH})
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${NONEUCLID_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS systemd)
# The engine's headers include GLM's (geometry/screen.hpp, reference.hpp).
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS libglm-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA
    ${noneuclid_pkg_out}/control/postinst ${noneuclid_pkg_out}/control/prerm
    ${noneuclid_pkg_out}/control/postrm ${noneuclid_pkg_out}/control/conffiles)
# Each package's description, its first line the synopsis (CPACK_PACKAGE_DESCRIPTION_SUMMARY is
# left unset: CPack would put it first in both).
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION "curved space in real time, for a Raspberry Pi kiosk
Bodies fly through a two-dimensional world of constant curvature K, from -1
(hyperbolic) through 0 (flat) to +1 (spherical), and K can be turned while
everything moves. The program draws into the Linux framebuffer and reads
arcade buttons through libgpiod or key events; it also runs in an X11 window
(where linked) and renders PNG pictures.
.
The package installs the program, the board files of the Raspberry Pi 3, 4, 5
and Zero 2 W, a board override in /etc/noneuclid/board.toml, and a systemd
unit that runs the kiosk on the first console as the user noneuclid (made at
install). The unit is not enabled: sudo systemctl enable --now noneuclid.")
set(CPACK_DEBIAN_DEV_DESCRIPTION "curved space in real time: the engine as a library
The noneuclid engine (worlds of constant curvature K from -1 to +1, their
bodies and game, fixed-point geometry and a CPU line rasteriser) for other
programs: its C++ headers and static libraries, the C interface noneuclid.h
(with libnoneuclid.so in a private directory, for C and Python's ctypes, where
built), and a CMake package: find_package(noneuclid) and
target_link_libraries(app noneuclid::engine) or noneuclid::capi.")
# dpkg-shlibdeps looks for a cross build's libraries in the target's multiarch directories
# (Debian's foreign-architecture packages, e.g. libpng-dev:arm64), as a native build's in its own.
set(CPACK_PROJECT_CONFIG_FILE ${noneuclid_pkg_out}/cpack-env.cmake)
file(WRITE ${CPACK_PROJECT_CONFIG_FILE} "set(ENV{DEB_HOST_ARCH} ${NONEUCLID_DEB_ARCH})\n")
# A package installs under /usr, where the paths compiled into the program, its unit and the
# maintainer scripts must point: a build for another prefix (a default build directory's
# /usr/local) makes none. `cpack -G DEB` there stops with the reason (cpack reads this file
# before it packs anything; tests/cli: cli_cpack_needs_usr).
if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
    file(APPEND ${CPACK_PROJECT_CONFIG_FILE} "if(CPACK_GENERATOR STREQUAL \"DEB\")
    message(FATAL_ERROR \"noneuclid: this build directory installs under ${CMAKE_INSTALL_PREFIX}, and a Debian \"
        \"package installs under /usr (the paths compiled into the program, its unit and its scripts are the \"
        \"package's): configure a build with -DCMAKE_INSTALL_PREFIX=/usr, or use the amd64, arm64 or armhf preset \"
        \"(platform/debian/build-packages).\")
endif()
")
endif()
include(CPack)
