# Compares the C++ riftc generates for one pack, verbatim, with the files kept
# under tests/compiler/generated/<case>/ (without #line directives, so adding
# a comment to a .rules file changes nothing).
#   cmake -DRIFTC=<riftc> -DRULES=<pack.rules> -DEXPECTED=<dir> -DWORK=<dir> [-DUPDATE=ON]
#         -P run_generated_golden.cmake
# With -DUPDATE=ON the expected files are rewritten instead (after an
# intended change of the generated code: review the diff before committing).
file(REMOVE_RECURSE "${WORK}")
execute_process(
  COMMAND "${RIFTC}" "${RULES}" -o "${WORK}" --no-line-directives
  RESULT_VARIABLE status
  ERROR_VARIABLE err
  TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "riftc failed on ${RULES}:\n${err}")
endif()
file(GLOB generated RELATIVE "${WORK}" "${WORK}/*.hpp" "${WORK}/*.cpp")
if(NOT generated)
  message(FATAL_ERROR "riftc wrote nothing into ${WORK}")
endif()
set(differ "")
foreach(name IN LISTS generated)
  file(READ "${WORK}/${name}" got)
  if(UPDATE)
    file(WRITE "${EXPECTED}/${name}" "${got}")
    continue()
  endif()
  if(NOT EXISTS "${EXPECTED}/${name}")
    list(APPEND differ "${name} (no expected file)")
    continue()
  endif()
  file(READ "${EXPECTED}/${name}" expected)
  if(NOT got STREQUAL expected)
    list(APPEND differ "${name}")
  endif()
endforeach()
if(differ)
  message(FATAL_ERROR
    "generated code differs from ${EXPECTED}: ${differ}\n"
    "compare: diff -r ${EXPECTED} ${WORK}\n"
    "if the change is intended, rerun this script with -DUPDATE=ON and review the diff")
endif()
