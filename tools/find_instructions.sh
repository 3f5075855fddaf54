#!/bin/sh
# Instructions per WheelContactFinder::find of the spacing bench's rolling
# wheel (docs/terrain.md): two callgrind runs of different length, the
# difference of find's inclusive count over the difference of its calls
# (validate() runs once a find), so the scenario's set-up cancels.
# Usage: tools/find_instructions.sh <wtc_bench_spacing> <mm> [compact|prisms]
set -e
bench=$1
mm=$2
storage=${3:-compact}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for t in 0.01 0.3; do
  valgrind --tool=callgrind --callgrind-out-file="$out/$t" --toggle-collect='*fieldSearch*' "$bench" \
    --benchmark_filter="FieldSearch/$storage/$mm\$" --benchmark_min_time=$t >/dev/null 2>&1
done
# find's inclusive count, and the calls of validate() from it.
inclusive() {
  callgrind_annotate --inclusive=yes "$1" 2>/dev/null | awk '/WheelContactFinder::find\(/ {gsub(",", "", $1); print $1; exit}'
}
calls() {
  callgrind_annotate --tree=calling --inclusive=yes "$1" 2>/dev/null |
    awk '/\*  .*WheelContactFinder::find\(/ {on = 1; next} on && /validate/ {
           if (match($0, /\(([0-9,]+)x\)/)) {c = substr($0, RSTART + 1, RLENGTH - 3); gsub(",", "", c); print c; exit}}'
}
i1=$(inclusive "$out/0.01"); i2=$(inclusive "$out/0.3")
c1=$(calls "$out/0.01"); c2=$(calls "$out/0.3")
echo "FieldSearch/$storage/$mm: $(( (i2 - i1) / (c2 - c1) )) instructions a find ($(( c2 - c1 )) calls)"
