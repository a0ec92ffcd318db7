# Runs a command and checks its exit status and output.
#
#   cmake -DCMD=<program;arg;...> -DEXPECT_CODE=<n> [-DEXPECT_REGEX=<regex>] -P cli_expect.cmake
#
# CMD is a CMake list (inside add_test, quote the whole "-DCMD=..." argument). The regex is
# matched against stdout followed by stderr; an empty or absent regex is not checked.

if(NOT DEFINED CMD OR "${CMD}" STREQUAL "")
  message(FATAL_ERROR "cli_expect.cmake: CMD is not set")
endif()
if(NOT DEFINED EXPECT_CODE)
  message(FATAL_ERROR "cli_expect.cmake: EXPECT_CODE is not set")
endif()

execute_process(
  COMMAND ${CMD}
  RESULT_VARIABLE code
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
set(output "${out}${err}")
message("${output}")

if(NOT "${code}" STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "cli_expect.cmake: '${CMD}' exited with '${code}', expected ${EXPECT_CODE}")
endif()
if(DEFINED EXPECT_REGEX AND NOT "${EXPECT_REGEX}" STREQUAL "")
  if(NOT output MATCHES "${EXPECT_REGEX}")
    message(FATAL_ERROR "cli_expect.cmake: output does not match '${EXPECT_REGEX}'")
  endif()
endif()
