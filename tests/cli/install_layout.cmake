# `cmake --install` into a scratch prefix: the binary, every board file, the systemd unit, the
# manual page and the documents land where docs/kiosk.md says, and the unit starts the
# installed binary.
#   cmake -DBUILD=<build dir> -DPREFIX=<scratch> -DSOURCE=<source dir> -P install_layout.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${rc}): ${err}")
endif()
foreach(f bin/noneuclid lib/systemd/system/noneuclid.service)
    if(NOT EXISTS ${PREFIX}/${f})
        message(FATAL_ERROR "${PREFIX}/${f} was not installed")
    endif()
endforeach()
file(GLOB boards RELATIVE ${SOURCE}/boards ${SOURCE}/boards/*.toml)
list(LENGTH boards n)
if(n LESS 5)
    message(FATAL_ERROR "expected at least 5 board files in ${SOURCE}/boards, found ${n}")
endif()
foreach(b ${boards})
    if(NOT EXISTS ${PREFIX}/share/noneuclid/boards/${b})
        message(FATAL_ERROR "board file ${b} was not installed to ${PREFIX}/share/noneuclid/boards")
    endif()
endforeach()
file(READ ${PREFIX}/lib/systemd/system/noneuclid.service unit)
# The unit starts the binary with its configure-time path: the install prefix of the build.
execute_process(COMMAND ${CMAKE_COMMAND} -L -N ${BUILD} OUTPUT_VARIABLE cache)
string(REGEX MATCH "CMAKE_INSTALL_PREFIX:PATH=([^\n]*)" _ "${cache}")
set(configured ${CMAKE_MATCH_1})
foreach(want "ExecStart=${configured}/bin/noneuclid run --display fbdev" "Conflicts=getty@tty1.service"
             "TTYPath=/dev/tty1" "Restart=always" "SupplementaryGroups=video input gpio audio" "StandardInput=tty"
             "StateDirectory=noneuclid")
    string(FIND "${unit}" "${want}" at)
    if(at LESS 0)
        message(FATAL_ERROR "the installed unit lacks '${want}':\n${unit}")
    endif()
endforeach()
# The installed binary finds the installed boards when told where (NONEUCLID_BOARDS).
execute_process(COMMAND ${CMAKE_COMMAND} -E env NONEUCLID_BOARDS=${PREFIX}/share/noneuclid/boards
                ${PREFIX}/bin/noneuclid run --display fbdev:/nonexistent/fb --board rpi4 --input none
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT err MATCHES "board Raspberry Pi 4[^\n]*${PREFIX}/share/noneuclid/boards/rpi4.toml" OR NOT rc EQUAL 2)
    message(FATAL_ERROR "the installed binary did not take rpi4 from the installed boards (exit ${rc}):\n${err}")
endif()
# The manual page, when help2man made one; the documents. The Debian package's system files
# (the user, the state directory, the udev rule, the board override) are not part of a plain
# install: systemd would not read them under /usr/local.
if(EXISTS ${BUILD}/man/noneuclid.1.gz AND NOT EXISTS ${PREFIX}/share/man/man1/noneuclid.1.gz)
    message(FATAL_ERROR "the manual page was made but not installed to ${PREFIX}/share/man/man1")
endif()
if(NOT EXISTS ${PREFIX}/share/doc/noneuclid/kiosk.md)
    message(FATAL_ERROR "the documents were not installed to ${PREFIX}/share/doc/noneuclid")
endif()
foreach(f lib/sysusers.d/noneuclid.conf lib/tmpfiles.d/noneuclid.conf lib/udev/rules.d/60-noneuclid-gpio.rules
          share/doc/noneuclid/copyright)
    if(EXISTS ${PREFIX}/${f})
        message(FATAL_ERROR "${PREFIX}/${f} was installed: it is the Debian package's alone")
    endif()
endforeach()
message(STATUS "installed: bin/noneuclid, ${n} board files, the unit, the documents")
