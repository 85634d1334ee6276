#!/usr/bin/env bash
# Installs this build of rift into a temporary prefix, builds the standalone
# projects examples/custom-criterion and examples/first-rule against it with
# find_package(rift), and runs them: the new criterion must tear the cloth,
# the tutorial's rule must turn 16 quads into 64 triangles. Then a project
# whose pack imports a pack of its own (tests/install/imported_pack).
set -euo pipefail
build_dir=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$source_dir/examples/custom-criterion" -B "$work/build" -G Ninja \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" > "$work/build.log" || { cat "$work/build.log"; exit 1; }

"$work/build/my_rift" list | grep -q "edge_strain" || { echo "edge_strain is not listed"; exit 1; }
"$work/build/my_rift" run "$source_dir/examples/custom-criterion/cloth.toml" --steps 1500 \
    --out "$work/out" --quiet
# The CSV's tears column (the fifth) must end above zero.
tears=$(tail -n 1 "$work/out/cloth.csv" | cut -d, -f5)
echo "tears after 1500 steps: $tears"
awk -v t="$tears" 'BEGIN { exit !(t > 0) }'
test -s "$work/out/cloth.pvd"

# A pack importing another that nothing else names: the simulator lists the
# importing pack only, and has both, each rule listed once, under its pack.
cmake -S "$source_dir/tests/install/imported_pack" -B "$work/imported" -G Ninja \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure3.log" \
  || { cat "$work/configure3.log"; exit 1; }
cmake --build "$work/imported" > "$work/build3.log" || { cat "$work/build3.log"; exit 1; }
"$work/imported/edge_sim" list > "$work/imported.txt"
grep -q "^pack edge_criteria (2D)" "$work/imported.txt" || { cat "$work/imported.txt"; exit 1; }
grep -q "^pack cuts (2D)" "$work/imported.txt" || { cat "$work/imported.txt"; exit 1; }
test "$(grep -c '^    cut$' "$work/imported.txt")" = 1 || { cat "$work/imported.txt"; exit 1; }

# The tutorial's project: one rule applied by a small program (docs/tutorial.md).
cmake -S "$source_dir/examples/first-rule" -B "$work/first" -G Ninja \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure2.log" \
  || { cat "$work/configure2.log"; exit 1; }
cmake --build "$work/first" > "$work/build2.log" || { cat "$work/build2.log"; exit 1; }
"$work/first/fan_faces" "$work/fan" | tee "$work/fan.log"
grep -q "faces=64" "$work/fan.log"
test -s "$work/fan/frame_000000.png"
