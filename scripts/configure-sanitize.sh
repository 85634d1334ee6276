#!/usr/bin/env bash
# Configures the clang build with AddressSanitizer, UndefinedBehaviorSanitizer
# and the libFuzzer targets (docs/reliability.md): build/sanitize, or the
# folder given. -O1 keeps the tests fast enough; line tables give stack
# traces with file and line; NDEBUG is not set, so assertions are checked.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/sanitize}
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" \
  -DRIFT_WERROR=ON -DRIFT_BUILD_FUZZERS=ON -DRIFT_BUILD_BENCHMARKS=OFF -DRIFT_BUILD_CGAL_TESTS=OFF \
  "${@:2}"
