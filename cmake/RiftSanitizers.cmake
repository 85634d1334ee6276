# RIFT_SANITIZE: every target of the tree (runtime, compiler, generated packs,
# tests) is built with AddressSanitizer and UndefinedBehaviorSanitizer, and
# any finding stops the program (no recovery), so a test with a finding fails.
# RIFT_BUILD_FUZZERS adds libFuzzer's coverage instrumentation to the same
# build, so that one build gives both the sanitizer tests and the fuzzers
# (docs/reliability.md).
if(RIFT_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "RIFT_BUILD_FUZZERS needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(RIFT_SANITIZE ON CACHE BOOL "" FORCE)
endif()

if(RIFT_SANITIZE)
  set(rift_sanitizer_flags -fsanitize=address,undefined -fno-sanitize-recover=all
                           -fno-omit-frame-pointer)
  add_compile_options(${rift_sanitizer_flags})
  add_link_options(-fsanitize=address,undefined)
  if(RIFT_BUILD_FUZZERS)
    add_compile_options(-fsanitize=fuzzer-no-link)
  endif()
endif()
