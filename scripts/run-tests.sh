#!/usr/bin/env bash
# Command (b) of the README, and exactly what CI runs (.ci/run): set up a
# fresh Debian machine, build everything (warnings are errors) and run the
# whole test suite; then the reliability jobs of docs/reliability.md: the
# clang ASan+UBSan build with the fast suites, each fuzz target for a short
# time, and clang-tidy. RIFT_RELIABILITY=0 runs the first job alone.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
jobs=$(nproc 2>/dev/null || echo 2)

# job NAME COMMAND...: runs one job and says how long it took.
job() {
  local name=$1 start=$SECONDS
  shift
  echo "=== job $name"
  "$@"
  echo "=== job $name: $((SECONDS - start)) s"
}

release() {
  cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIFT_WERROR=ON
  cmake --build build/release -j "$jobs"
  ctest --test-dir build/release --output-on-failure -j "$jobs"
}

job release release
if [ "${RIFT_RELIABILITY:-1}" != 0 ]; then
  # The clang ASan+UBSan build is shared by the sanitizer tests and the
  # fuzzers; clang-tidy configures a tree of its own (build/tidy) for the
  # compile commands of each source.
  job sanitizers ./scripts/sanitize-tests.sh
  job fuzz ./scripts/fuzz.sh all "${RIFT_FUZZ_SECONDS:-10}" -seed=1
  job clang-tidy ./scripts/clang-tidy.sh
fi
