#!/usr/bin/env bash
# Every row of the speed table of docs/performance.md ("The whole table"),
# measured in one run of this script so that the ratios compare figures taken
# side by side, then printed as a Markdown table by scripts/bench-table.py.
#
#   scripts/bench-table.sh [BUILD] [OUT]     # BUILD: build/release, OUT: bench-table
#
# BUILD must be a Release build with the benchmarks (RIFT_BUILD_BENCHMARKS, on
# by default when Google Benchmark is found). OUT receives every benchmark's
# JSON and the scenes made for the 10⁶-vertex rows. Fig. 13's row needs the
# shared liver mesh: RIFT_MESHES (default ../shared/meshes beside the
# repository); without it the row is left out. About 15 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-bench-table}
meshes=${RIFT_MESHES:-$(cd .. && pwd)/shared/meshes}
bench=$build/tests/bench
rift=$build/rift
mkdir -p "$out"
for b in "$rift" "$bench/rift_bench_tear" "$bench/rift_bench_scaling" "$bench/rift_bench_threads" \
  "$bench/rift_bench_corotational"; do
  if [ ! -x "$b" ]; then
    echo "bench-table: $b is missing; build $build (Release, with benchmarks) first" >&2
    exit 1
  fi
done

step() { echo "bench-table: $*" >&2; }
# Google Benchmark runs: interleaved repetitions (REPS, default 3), as JSON.
gbench() {
  local name=$1 binary=$2
  shift 2
  step "$name"
  "$binary" --benchmark_format=json --benchmark_repetitions="${REPS:-3}" \
    --benchmark_enable_random_interleaving=true "$@" > "$out/$name.json"
}
# rift bench runs, one JSON object per line, ROUNDS rounds interleaved over
# the scenes: `rbench NAME ROUNDS STEPS SCENE...`. With WARM=1 (set-ups),
# each timed run comes right after an untimed run of the same scene: on a
# virtual machine, memory the guest touches for the first time (or again
# after the host took it back) can cost more than the set-up's own work, and
# by a varying amount (docs/performance.md, "The run of `528f040`"); the run
# before leaves warm the memory the timed run reuses.
rbench() {
  local name=$1 rounds=$2 steps=$3
  shift 3
  step "$name"
  : > "$out/$name.jsonl"
  for _ in $(seq "$rounds"); do
    for scene in "$@"; do
      if [ "${WARM:-0}" = 1 ]; then
        "$rift" bench "$scene" --steps "$steps" --threads 1 --json > /dev/null
      fi
      "$rift" bench "$scene" --steps "$steps" --threads 1 --json >> "$out/$name.jsonl"
    done
  done
}
# A copy of scene $1 as $out/$2.toml with its mesh source replaced by $3.
with_source() {
  sed "s|^source = .*|source = \"$3\"|" "$1" > "$out/$2.toml"
}

# One tear at 1000×1000 against 10×10: any spring, then the same inner tear at both sizes.
gbench tear "$bench/rift_bench_tear" --benchmark_filter='BM_OneTear/quads(_inner)?/(10|1000)/'

# Table 2: the paper's 10×10 cloths, basic step and both edge criteria.
table2=()
for mesh in quads triangles mixed; do
  for kind in basic global atomic; do table2+=("examples/table2/$mesh-$kind.toml"); done
done
rbench table2 5 2000 "${table2[@]}"

# The generated step against the hand-written reference cloth, 10² to 10⁶ vertices.
# Five repetitions: the table gives their medians and the fastest (a repetition
# now and then runs about 1.6× slower throughout, whatever the benchmark).
REPS=5 gbench scaling "$bench/rift_bench_scaling" --benchmark_min_time=0.1 \
  --benchmark_filter='BM_ScalingCloth(Rift/(quads|triangles)|Reference/(quads|triangles)_(atomic|cumulated))/(10|99|999)$'

# Set-up and peak memory at 10⁶ vertices: the paper's quad cloth (999² patches)
# and its 3D mass-spring block (99³ hexahedra), one step each.
# Each keeps its mass per vertex (so its time step stays stable): 0.1 kg over
# the 121 vertices of 10×10 quads, 1 kg over the 75 of 4×4×2 hexahedra.
with_source examples/table2/quads-basic.toml quads1m "grid:quad:999x999"
sed -i 's|^total = .*|total = 826.0|' "$out/quads1m.toml"
with_source examples/paper/fig12.toml hex1m "block:hex:99x99x99"
sed -i 's|^total = .*|total = 13333.0|' "$out/hex1m.toml"
WARM=1 rbench setup_quads 2 1 "$out/quads1m.toml"
WARM=1 rbench setup_hex 1 1 "$out/hex1m.toml"
step "reference peak memory"
/usr/bin/time -f "%M" -o "$out/reference_rss_kb.txt" "$bench/rift_bench_scaling" \
  --benchmark_filter='BM_ScalingClothReference/quads_cumulated/999$' --benchmark_min_time=0.01 \
  > /dev/null

# RK4 at 10⁶ quads on one and two threads: one process per thread count and
# 3 s of steps each. In one process stepping the same cloth on both counts in
# turn, the second ran up to 1.4× slower, and half a second is two steps
# (docs/performance.md, "The run of `30a6001`").
for t in 1 2; do
  REPS=1 gbench "threads$t" "$bench/rift_bench_threads" --benchmark_min_time=3 \
    --benchmark_filter="BM_ThreadsRk4Cloth/1000/$t/"
done

# The co-rotational tetrahedron, per element.
gbench corotational "$bench/rift_bench_corotational"

# Fig. 13 with its vertex stress criterion and without any criterion.
if [ -f "$meshes/liver.msh" ]; then
  with_source examples/paper/fig13.toml fig13 "$meshes/liver.msh"
  # Without its [[criterion]] table and [output] (the rest of the file).
  sed '/^\[\[criterion\]\]/,$d' "$out/fig13.toml" > "$out/fig13_nocrit.toml"
  rbench fig13 3 300 "$out/fig13.toml" "$out/fig13_nocrit.toml"
else
  step "no $meshes/liver.msh: fig. 13's row is left out (set RIFT_MESHES)"
  rm -f "$out/fig13.jsonl"
fi

# Building a G-map against CGAL's Generalized_map (only built with CGAL's headers).
# glibc's malloc returns large freed blocks to the system (mmap, trimming) or
# keeps them, depending on the sizes it saw free before: the builds measured
# after a 1000² build in the same process reused warm memory, the others
# faulted in fresh pages at every build, which once made CGAL look 2.6 times
# slower than it is (docs/performance.md, "The run of `fdad719`"). Every build
# here reuses the heap's memory: the figures compare the two builds' work.
if [ -x "$bench/rift_bench_gmap" ]; then
  GLIBC_TUNABLES=glibc.malloc.trim_threshold=4294967296:glibc.malloc.mmap_threshold=4294967296 \
    gbench gmap "$bench/rift_bench_gmap" --benchmark_filter='BM_(Rift|CgalBare)_Build/'
else
  rm -f "$out/gmap.json"
fi

python3 scripts/bench-table.py "$out"
