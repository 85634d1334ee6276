# Folders depend one way. Given an order of folders, lowest first, a file of
# one folder may include headers of its own folder and of folders listed
# before it, never of a folder listed after it. An order that every include
# respects is what makes the folders' dependencies free of cycles: a cycle
# would need at least one include that goes up. Fails naming every include
# that goes up, with the file and line it is on.
#   cmake -DROOT=<dir holding the folders> -DPREFIX=<text before the folder
#         in an include, e.g. "rift/"> -DORDER=<a,b,c> [-DWHAT=<name>]
#         -P folder_order.cmake
# The order is the one docs/architecture.md describes; a new dependency
# between two folders that the order does not allow means either a folder
# is in the wrong place in the order (move it, if no include goes up then)
# or a piece of code is in the wrong folder.
cmake_minimum_required(VERSION 3.20)

if(NOT ROOT OR NOT DEFINED PREFIX OR NOT ORDER)
  message(FATAL_ERROR "usage: cmake -DROOT=<dir> -DPREFIX=<include prefix> -DORDER=<a,b,c> "
                      "-P folder_order.cmake")
endif()
string(REPLACE "," ";" ORDER "${ORDER}")
if(NOT WHAT)
  set(WHAT "${ROOT}")
endif()

# Every folder under ROOT must have a place in the order, so that a new
# folder cannot slip past the check.
file(GLOB entries RELATIVE "${ROOT}" "${ROOT}/*")
foreach(entry IN LISTS entries)
  if(IS_DIRECTORY "${ROOT}/${entry}" AND NOT entry IN_LIST ORDER)
    message(FATAL_ERROR "${WHAT}: folder ${entry}/ has no place in the order (${ORDER}): "
                        "add it to the test's ORDER where its includes allow")
  endif()
endforeach()

set(errors "")
set(files_read 0)
set(rank 0)
foreach(folder IN LISTS ORDER)
  set(rank_${folder} ${rank})
  math(EXPR rank "${rank} + 1")
endforeach()
foreach(folder IN LISTS ORDER)
  file(GLOB_RECURSE sources "${ROOT}/${folder}/*.hpp" "${ROOT}/${folder}/*.cpp"
       "${ROOT}/${folder}/*.y" "${ROOT}/${folder}/*.re")
  foreach(source IN LISTS sources)
    math(EXPR files_read "${files_read} + 1")
    file(STRINGS "${source}" lines)
    set(line_number 0)
    foreach(line IN LISTS lines)
      math(EXPR line_number "${line_number} + 1")
      if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]+\"${PREFIX}([A-Za-z0-9_]+)/")
        continue()
      endif()
      set(target "${CMAKE_MATCH_1}")
      if(NOT DEFINED rank_${target})
        continue()  # not a folder of ROOT (e.g. a third-party header)
      endif()
      if(rank_${target} GREATER rank_${folder})
        file(RELATIVE_PATH shown "${ROOT}" "${source}")
        string(STRIP "${line}" include)
        string(APPEND errors "\n  ${shown}:${line_number}: ${folder}/ includes ${target}/, "
                             "which comes after it: ${include}")
      endif()
    endforeach()
  endforeach()
endforeach()

if(files_read EQUAL 0)
  message(FATAL_ERROR "${WHAT}: no source file found under ${ROOT}")
endif()
list(JOIN ORDER " -> " shown_order)
if(errors)
  message(FATAL_ERROR "${WHAT}: folders must depend one way, in the order ${shown_order} "
                      "(docs/architecture.md); includes that go up:${errors}")
endif()
message(STATUS "${WHAT}: ${files_read} files, every include follows ${shown_order}")
