# The compiler's folders depend one way: emit/ renders the plans of lower/
# and decides nothing the checks decided, so nothing it includes, directly or
# through the headers of lower/, ir/, ast/ and diag/, may come from check/,
# resolve/, parse/ or driver/. Follows the quoted includes of every file of
# compiler/emit and fails naming the first path that breaks the rule.
#   cmake -DCOMPILER=<repo>/compiler -P emit_dependencies.cmake
cmake_minimum_required(VERSION 3.20)

if(NOT COMPILER)
  message(FATAL_ERROR "usage: cmake -DCOMPILER=<repo>/compiler -P emit_dependencies.cmake")
endif()

set(forbidden "check/" "resolve/" "parse/" "driver/")
file(GLOB queue RELATIVE "${COMPILER}" "${COMPILER}/emit/*.hpp" "${COMPILER}/emit/*.cpp")
list(LENGTH queue count)
if(count EQUAL 0)
  message(FATAL_ERROR "no file under ${COMPILER}/emit")
endif()
set(seen ${queue})
# How each file was reached, for the message: "emit/a.cpp -> lower/b.hpp -> ...".
foreach(f IN LISTS queue)
  set(via_${f} "${f}")
endforeach()
while(queue)
  list(POP_FRONT queue file)
  file(STRINGS "${COMPILER}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" inc "${line}")
    foreach(bad IN LISTS forbidden)
      string(FIND "${inc}" "${bad}" at)
      if(at EQUAL 0)
        message(FATAL_ERROR "compiler/emit must not depend on ${bad}: ${via_${file}} -> ${inc}")
      endif()
    endforeach()
    if(EXISTS "${COMPILER}/${inc}" AND NOT inc IN_LIST seen)
      list(APPEND seen "${inc}")
      list(APPEND queue "${inc}")
      set(via_${inc} "${via_${file}} -> ${inc}")
    endif()
  endforeach()
endwhile()
list(LENGTH seen total)
list(JOIN forbidden ", " named)
message(STATUS "compiler/emit reaches ${total} files of the compiler, none from ${named}")
