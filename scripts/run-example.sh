#!/usr/bin/env bash
# Command (a) of the README: set up a fresh Debian machine, build rift and
# run it on bundled examples.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j "$jobs" --target rift

echo "== rift info grid:quad:10x10 (the paper's 10x10 cloth, generated)"
./build/release/rift info grid:quad:10x10
echo "== rift info examples/meshes/beam.msh (a bundled tetrahedral beam)"
./build/release/rift info examples/meshes/beam.msh
