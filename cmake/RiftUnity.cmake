# rift_unity_build(target): compiles a library's sources in batches of
# neighbouring files (CMake's unity builds). Each batch parses Eigen, the
# standard library and the runtime's headers once instead of once per file:
# the runtime and riftc's library took 0.40x the CPU time in batches (GCC 12,
# Release: 386-430 s as 112 files, 157-173 s as 14 batches), and the
# sanitizer build gains about as much. Helpers in anonymous namespaces must
# then have names of their own within a target: two helpers of one signature
# fail to compile, and a helper that overloads a declared function can take
# another file's calls (docs/architecture.md, "Build types"). clang-tidy
# checks each source alone (scripts/clang-tidy.sh), so a missing #include
# still fails CI. -DRIFT_UNITY_BUILD=OFF compiles file by file (faster after
# editing one file).
option(RIFT_UNITY_BUILD "Compile the runtime, riftc and the CLI in batches of sources" ON)
set(RIFT_UNITY_BUILD_BATCH 8 CACHE STRING "Library sources per unity batch")

function(rift_unity_build target)
  if(RIFT_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                                               UNITY_BUILD_BATCH_SIZE ${RIFT_UNITY_BUILD_BATCH})
  endif()
endfunction()
