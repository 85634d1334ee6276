#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz, each for a given time, and fails
# on the first crash, hang or memory blow-up (docs/reliability.md).
#
#   scripts/fuzz.sh TARGET|all [SECONDS] [libFuzzer flags...]
#   scripts/fuzz.sh gmsh 600            # ten minutes on the Gmsh reader
#   scripts/fuzz.sh all 10 -seed=1      # what CI runs
#
# Targets run one per core at a time (RIFT_FUZZ_PARALLEL to change it).
# Targets: rules obj gmsh medit vtu vtk scene. The fuzzers are built with
# clang, ASan and UBSan in build/sanitize (RIFT_FUZZ_BUILD to change it),
# configured here if needed. Inputs the fuzzer finds interesting go to
# build/sanitize/fuzz/corpus/TARGET (not the repository); a crashing input
# is saved as build/sanitize/fuzz/artifacts/TARGET/crash-... : add it to
# tests/fuzz/corpus/TARGET/ once fixed, so that it stays a regression test.
set -euo pipefail
cd "$(dirname "$0")/.."

all_targets=(rules obj gmsh medit vtu vtk scene)
target=${1:-all}
seconds=${2:-60}
shift $(($# < 2 ? $# : 2))
build=${RIFT_FUZZ_BUILD:-build/sanitize}

if [ "$target" = all ]; then
  targets=("${all_targets[@]}")
else
  targets=("$target")
fi

if [ ! -f "$build/build.ninja" ]; then
  ./scripts/configure-sanitize.sh "$build"
fi
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" \
  --target $(printf 'rift_fuzz_%s ' "${targets[@]}")

# fuzz_one TARGET: runs one target, says what it found, returns non-zero on
# a finding.
fuzz_one() {
  local t=$1
  local corpus="$build/fuzz/corpus/$t" artifacts="$build/fuzz/artifacts/$t"
  local log="$build/fuzz/$t.log"
  mkdir -p "$corpus" "$artifacts"
  # -timeout: one input taking more than 10 s is a hang. -rss_limit_mb and
  # -malloc_limit_mb: inputs are at most a few KB, so a reader that asks for
  # 512 MB at once believed a header it should not have.
  if "$build/tests/fuzz/rift_fuzz_$t" "$corpus" "tests/fuzz/corpus/$t" \
      -dict="tests/fuzz/dict/$t.dict" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len=16384 \
      -artifact_prefix="$artifacts/" -print_final_stats=1 "${flags[@]}" >"$log" 2>&1; then
    local runs
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    echo "fuzz: $t: ${runs:-?} inputs in ${seconds}s, no finding"
  else
    echo "fuzz: $t FAILED; the input is in $artifacts/, the log in $log:" >&2
    grep -m1 -A30 -E '^==[0-9]+==|^SUMMARY|terminate called|uncaught' "$log" >&2 || tail -40 "$log" >&2
    return 1
  fi
}

# One target per core at a time: each libFuzzer process is single-threaded.
flags=("$@")
parallel=${RIFT_FUZZ_PARALLEL:-$(nproc 2>/dev/null || echo 2)}
status=0
running=0
for t in "${targets[@]}"; do
  if [ "$running" -ge "$parallel" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  echo "fuzz: $t for ${seconds}s"
  fuzz_one "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
