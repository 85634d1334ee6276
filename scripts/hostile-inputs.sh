#!/usr/bin/env bash
# The hostile-input table of docs/reliability.md: generates one input of each
# hostile class, runs `rift info` on it and prints a Markdown row with rift's
# message (the first line it writes to stderr, or "(read)" and the first line
# of the counts when it writes none), the exit status and the peak memory (maximum
# resident set size, /usr/bin/time). The unit tests of each class are in
# tests/io/hostile_inputs_test.cpp and tests/io/reservation_test.cpp; this
# script measures what a user sees, at full size (a 60 MB lying header, a
# 100 MB line), which the unit tests do not write to disk.
#
#   scripts/hostile-inputs.sh [path/to/rift]     (default build/release/rift)
set -euo pipefail

rift=${1:-build/release/rift}
[[ -x $rift ]] || { echo "hostile-inputs: no rift executable at $rift" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "hostile-inputs: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

msh22='$MeshFormat
2.2 0 8
$EndMeshFormat'
tri_obj='v 0 0 0
v 1 0 0
v 0 1 0
f 1 2 3'
vtk_head='# vtk DataFile Version 3.0
hostile
ASCII
DATASET UNSTRUCTURED_GRID'
hex_points='POINTS 8 double
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1'

# Node lines "k x y 0.25" for k = 1..n (nodes 1, 2, 3 make a proper triangle).
nodes() { awk -v n="$1" 'BEGIN { for (k = 1; k <= n; ++k) printf "%d 0.%d 0.%d 0.25\n", k, k, (k * k) % 7 }'; }

make_inputs() {
  { echo "$msh22"; printf '$Nodes\n2147483647\n'; nodes 2300000; } >"$dir/billions_of_nodes.msh"
  # The same data with an honest count and a triangle: the memory to compare with.
  { echo "$msh22"; printf '$Nodes\n2300000\n'; nodes 2300000
    printf '$EndNodes\n$Elements\n1\n1 2 0 1 2 3\n$EndElements\n'; } >"$dir/honest_nodes.msh"
  { echo "$msh22"; printf '$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n2147483647\n'
    awk 'BEGIN { for (k = 1; k <= 2000000; ++k) printf "%d 2 0 1 2 3\n", k }'; } >"$dir/billions_of_elements.msh"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n' >"$dir/negative_index.obj"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n' >"$dir/overflowing_index.obj"
  { echo "$msh22"; printf '$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 0 1 2 -3\n$EndElements\n'; } >"$dir/negative_node.msh"
  printf 'v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$dir/nan.obj"
  printf 'v 0 -inf 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$dir/inf.obj"
  printf 'v 1e300 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$dir/1e300.obj"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n' >"$dir/zero_area.obj"
  { echo "$msh22"; printf '$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 0\n$EndNodes\n'
    printf '$Elements\n2\n1 4 0 1 2 3 4\n2 4 0 1 2 3 5\n$EndElements\n'; } >"$dir/zero_volume.msh"
  { echo "$vtk_head"; echo "$hex_points"; printf 'CELLS 1 9\n8 4 5 6 7 0 1 2 3\nCELL_TYPES 1\n12\n'; } >"$dir/inverted_hex.vtk"
  { echo "$vtk_head"; printf 'POINTS 6 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n'
    printf 'CELLS 1 9\n8 0 1 2 3 4 5 5 4\nCELL_TYPES 1\n12\n'; } >"$dir/collapsed_hex.vtk"
  { echo "$msh22"; printf '$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n'
    printf '$Elements\n3\n1 2 0 1 2 3\n2 4 0 1 2 3 4\n3 1 0 1 2\n$EndElements\n'; } >"$dir/mixed_dimensions.msh"
  { echo "$msh22"; printf '$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 0 1 2 3\n$EndElements\n'; } |
    sed 's/$/\r/' >"$dir/crlf.msh"
  { printf '\xEF\xBB\xBF'; echo "$tri_obj"; } >"$dir/byte_order_mark.obj"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1\0 0\nf 1 2 3\n' >"$dir/nul_byte.obj"
  { printf '# '; head -c 100000000 /dev/zero | tr '\0' x; printf '\n'; echo "$tri_obj"; } >"$dir/100MB_comment_line.obj"
  { printf 'v '; head -c 100000000 /dev/zero | tr '\0' 1; printf ' 0 0\n'; echo "$tri_obj" | tail -n +2; } >"$dir/100MB_number.obj"
  { printf '<VTKFile type="UnstructuredGrid"><UnstructuredGrid>\n'
    awk 'BEGIN { for (k = 0; k < 1000000; ++k) printf "<a>"; for (k = 0; k < 1000000; ++k) printf "</a>" }'
    printf '\n</UnstructuredGrid></VTKFile>\n'; } >"$dir/deeply_nested.vtu"
}

make_inputs
echo "| input | size | rift info says | exit | peak memory |"
echo "|---|---|---|---|---|"
for f in honest_nodes.msh billions_of_nodes.msh billions_of_elements.msh negative_index.obj overflowing_index.obj \
         negative_node.msh nan.obj inf.obj 1e300.obj zero_area.obj zero_volume.msh inverted_hex.vtk \
         collapsed_hex.vtk mixed_dimensions.msh crlf.msh byte_order_mark.obj nul_byte.obj \
         100MB_comment_line.obj 100MB_number.obj deeply_nested.vtu; do
  set +e
  /usr/bin/time -o "$dir/time" -f "%M" "$rift" info "$dir/$f" >"$dir/out" 2>"$dir/err"
  status=$?
  set -e
  # The first line of the message (or of the output when there is none),
  # without the temporary folder, cut at 200 characters.
  if [[ -s $dir/err ]]; then msg=$(head -n 1 "$dir/err"); else msg="(read) $(head -n 1 "$dir/out")"; fi
  msg=$(echo "$msg" | sed "s|$dir/||g" | cut -c 1-200 | tr -d '\r' | sed 's/|/\\|/g')
  size=$(stat -c %s "$dir/$f" | awk '{ s = $1; u = "B"; if (s >= 1e6) { s /= 1e6; u = "MB" } else if (s >= 1e3) { s /= 1e3; u = "kB" }; printf (u == "B" ? "%d %s" : "%.0f %s"), s, u }')
  peak=$(tail -n 1 "$dir/time" | awk '{ printf "%.0f MB", $1 / 1024 }')
  echo "| \`$f\` | $size | $msg | $status | $peak |"
done
