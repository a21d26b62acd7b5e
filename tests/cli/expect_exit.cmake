# Run a command and check its exit code and output.
#
#   cmake -DCMD=<program;arg;...> -DEXPECT=<code> [-DREGEX=<re>] [-DOUT_REGEX=<re>] -P expect_exit.cmake
#
# CMD     the command as a CMake list (emulator first when cross-compiling)
# EXPECT  the exit code it must return (default 0)
# REGEX   if given, stderr must match it
# OUT_REGEX  if given, stdout must match it
if(NOT DEFINED CMD OR CMD STREQUAL "")
    message(FATAL_ERROR "expect_exit.cmake: CMD not given")
endif()
if(NOT DEFINED EXPECT)
    set(EXPECT 0)
endif()

execute_process(
    COMMAND ${CMD}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE out
    ERROR_VARIABLE err)

# Echo what the program printed, so ctest --output-on-failure shows it.
if(NOT out STREQUAL "")
    message("--- stdout ---\n${out}")
endif()
if(NOT err STREQUAL "")
    message("--- stderr ---\n${err}")
endif()

list(JOIN CMD " " cmd_text)
if(NOT result STREQUAL "${EXPECT}")
    message(FATAL_ERROR "`${cmd_text}` exited with '${result}', expected ${EXPECT}")
endif()
if(DEFINED REGEX AND NOT err MATCHES "${REGEX}")
    message(FATAL_ERROR "stderr of `${cmd_text}` does not match '${REGEX}'")
endif()
if(DEFINED OUT_REGEX AND NOT out MATCHES "${OUT_REGEX}")
    message(FATAL_ERROR "stdout of `${cmd_text}` does not match '${OUT_REGEX}'")
endif()
