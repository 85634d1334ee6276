# The instruction set rift is compiled for, and the one floating-point rule
# every build keeps.
#
# RIFT_ARCH (a cache string):
#   auto (default)  x86-64-v3 (AVX2, FMA, BMI2) when the compiler takes it and
#                   the building machine runs it, else the compiler's default
#   none            the compiler's default target (a binary for any x86-64)
#   anything else   passed as -march=<value>
# The force loops and the integrator's sweeps gain the three-operand vector
# encodings: on the 10×10 cloths of Table 2 a step takes about 0.92 of the
# time of a build for plain x86-64 (docs/performance.md, "Compiled for
# x86-64-v3"). Not -march=native: with AVX-512, GCC 12 warns inside Eigen's
# packet code, and Eigen's wider packets would sum its dense products in
# another order on machines that have it.
#
# -ffp-contract=off, always: the compiler never fuses a multiply and an add
# into one rounding (FMA). Fusing is decided per expression and per inlined
# copy, so the same force evaluated in two places (the grouped and the atomic
# pass, a stage and its reference) could round differently, and tests check
# that such paths agree to the bit. With it, the instruction set changes the
# speed of rift's own loops, not their arithmetic (Eigen's dynamic-size
# operations may still sum in another order with AVX's wider packets).
include(CheckCXXCompilerFlag)
include(CheckCXXSourceRuns)

set(RIFT_ARCH "auto" CACHE STRING "Instruction set: auto (x86-64-v3 when the building machine runs it), none, or a -march value")

check_cxx_compiler_flag(-ffp-contract=off RIFT_HAS_FP_CONTRACT_OFF)
if(RIFT_HAS_FP_CONTRACT_OFF)
  add_compile_options(-ffp-contract=off)
endif()

if(RIFT_ARCH STREQUAL "auto")
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$" AND NOT CMAKE_CROSSCOMPILING)
    set(CMAKE_REQUIRED_FLAGS -march=x86-64-v3)
    # The program runs on the building machine: it says whether the binaries
    # built here, which the tests run, can use the instructions.
    check_cxx_source_runs([[
      int main() {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                       __builtin_cpu_supports("bmi2") ? 0 : 1;
      }]] RIFT_RUNS_X86_64_V3)
    unset(CMAKE_REQUIRED_FLAGS)
    if(RIFT_RUNS_X86_64_V3)
      add_compile_options(-march=x86-64-v3)
    else()
      message(STATUS "rift: building for the compiler's default x86-64 (no x86-64-v3 here)")
    endif()
  endif()
elseif(NOT RIFT_ARCH STREQUAL "none" AND NOT RIFT_ARCH STREQUAL "")
  add_compile_options(-march=${RIFT_ARCH})
endif()
