#!/usr/bin/env bash
# The sanitizer job (docs/reliability.md): builds the runtime, the compiler
# and the fast test suites with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build/sanitize, and runs them. Any finding
# aborts its test, so the job fails. The fuzzers share this build.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${RIFT_SANITIZE_BUILD:-build/sanitize}
jobs=$(nproc 2>/dev/null || echo 2)

# The suites that run here; the others need the generated packs or run long
# simulations (docs/reliability.md says which and why).
suites=(rift_gmap_tests rift_mesh_tests rift_sim_tests rift_scene_tests rift_io_tests
        rift_output_tests rift_cli_tests riftc_unit_tests riftc rift_fuzz_corpus_tests)

# Tests of those suites left to the release job: each runs a simulation of
# thousands of steps that takes 20 s to minutes under ASan at -O1, and
# exercises no code the faster tests of the same suite do not.
slow='^ImplicitEuler\.(HangingCloth|TearsTheCloth|UndampedStiffSprings)|^Bdf2\.(UndampedStiffSprings|TearsTheCloth)|^Cli\.(StiffBeamWithRk4|HeavilyTornCloth|TheSameSceneTwice|TheSame3DSceneTwice|AnyThreadCount)'

if [ ! -f "$build/build.ninja" ]; then
  ./scripts/configure-sanitize.sh "$build"
fi
cmake --build "$build" -j "$jobs" --target "${suites[@]}"

# detect_leaks: a leak is a finding too. halt_on_error: the first finding
# fails the test, with its stack trace in the test's output.
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Tests of suites not built here are listed as *_NOT_BUILT; the rest are the
# suites above, plus riftc's golden cases and include-path tests.
ctest --test-dir "$build" --output-on-failure -j "$jobs" \
  -E "_NOT_BUILT|^example_|^CustomCriterion|$slow"
