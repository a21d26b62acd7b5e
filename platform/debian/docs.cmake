# The manual page and the documents, for `cmake --install` and the Debian package (included from
# platform/CMakeLists.txt): noneuclid.1 is made from `noneuclid --help` and `--version` by
# help2man (Debian package help2man), so it lists every command and option the program has;
# noneuclid.h2m.in adds the sections --help does not have (files, environment, exit status).
# Without help2man there is no manual page, and configuring says so.

find_program(NONEUCLID_HELP2MAN help2man DOC "help2man, which makes the manual page from --help")
if(NONEUCLID_HELP2MAN)
    # help2man runs the program it is given; a cross build's runs under the emulator (qemu-user),
    # through a script named noneuclid so that the page is noneuclid(1).
    set(noneuclid_man_dir ${PROJECT_BINARY_DIR}/man)
    list(JOIN CMAKE_CROSSCOMPILING_EMULATOR " " noneuclid_emulator)
    file(GENERATE OUTPUT ${noneuclid_man_dir}/bin/noneuclid
         CONTENT "#!/bin/sh\nexec ${noneuclid_emulator} \"$<TARGET_FILE:noneuclid>\" \"$@\"\n"
         FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
    configure_file(${CMAKE_CURRENT_LIST_DIR}/noneuclid.h2m.in ${noneuclid_man_dir}/noneuclid.h2m @ONLY)
    # The page's date: the last commit's (reproducible), else the build's.
    if(DEFINED ENV{SOURCE_DATE_EPOCH})
        set(NONEUCLID_SOURCE_DATE_EPOCH $ENV{SOURCE_DATE_EPOCH})
    else()
        execute_process(COMMAND git -C ${PROJECT_SOURCE_DIR} log -1 --format=%ct
                        OUTPUT_VARIABLE NONEUCLID_SOURCE_DATE_EPOCH OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    endif()
    set(noneuclid_date_env)
    if(NONEUCLID_SOURCE_DATE_EPOCH)
        set(noneuclid_date_env SOURCE_DATE_EPOCH=${NONEUCLID_SOURCE_DATE_EPOCH})
    endif()
    add_custom_command(OUTPUT ${noneuclid_man_dir}/noneuclid.1.gz
        COMMAND ${CMAKE_COMMAND} -E env ${noneuclid_date_env} ${NONEUCLID_HELP2MAN} --no-info
                --include=${noneuclid_man_dir}/noneuclid.h2m --output=${noneuclid_man_dir}/noneuclid.1
                ${noneuclid_man_dir}/bin/noneuclid
        COMMAND gzip -9nf ${noneuclid_man_dir}/noneuclid.1
        DEPENDS noneuclid ${noneuclid_man_dir}/noneuclid.h2m
        COMMENT "Making the manual page noneuclid.1 from noneuclid --help (help2man)"
        VERBATIM)
    add_custom_target(noneuclid_man ALL DEPENDS ${noneuclid_man_dir}/noneuclid.1.gz)
    install(FILES ${noneuclid_man_dir}/noneuclid.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
    message(STATUS "help2man not found: no manual page (Debian: help2man)")
endif()

# The documents: the README and docs/ (text; the pictures stay in the repository).
file(GLOB noneuclid_docs ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${noneuclid_docs} DESTINATION ${CMAKE_INSTALL_DOCDIR})
