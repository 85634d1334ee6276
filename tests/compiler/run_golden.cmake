# Runs riftc on one golden case and compares its diagnostics with expected.txt.
#   cmake -DRIFTC=<riftc> -DCASE_DIR=<dir> -P run_golden.cmake
# The case folder holds case.rules, expected.txt (the exact diagnostics, caret
# lines included; empty when the case compiles cleanly) and optionally args.txt
# (extra riftc arguments, one per line). The expected exit status is 1 when
# expected.txt contains an error, 0 otherwise.
set(args "")
if(EXISTS "${CASE_DIR}/args.txt")
  file(STRINGS "${CASE_DIR}/args.txt" args)
endif()
execute_process(
  COMMAND "${RIFTC}" case.rules ${args}
  WORKING_DIRECTORY "${CASE_DIR}"
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 20)
file(READ "${CASE_DIR}/expected.txt" expected)
string(FIND "${expected}" ": error: " has_error)
if(has_error EQUAL -1)
  set(expected_status 0)
else()
  set(expected_status 1)
endif()
if(NOT "${err}" STREQUAL "${expected}")
  message(FATAL_ERROR "diagnostics differ from expected.txt\n--- expected\n${expected}--- got\n${err}---")
endif()
if(NOT "${status}" STREQUAL "${expected_status}")
  message(FATAL_ERROR "exit status ${status}, expected ${expected_status}")
endif()
