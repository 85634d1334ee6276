# rift_set_warnings(target): the warning flags every rift target is built with.
# With RIFT_WERROR (on in CI) warnings are errors.
function(rift_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual)
  if(RIFT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
