#!/bin/sh
# Instructions per WheelContactFinder::find of the spacing bench's rolling
# wheel (docs/terrain.md), or per TyreModel::step (the whole wheel step:
# the search and the forces): two callgrind runs of different length, the
# difference of the function's inclusive count over the difference of its
# calls, so the scenario's set-up cancels.
# Usage: tools/find_instructions.sh <wtc_bench_spacing> <mm> [compact|prisms] [find|step] [rough|smooth|flat]
# (the ground: rough, the default, is the bench's rough surface; smooth and
# flat, compact storage only, its relief alone and a level plane)
set -e
bench=$1
mm=$2
storage=${3:-compact}
what=${4:-find}
ground=${5:-rough}
case $ground in
  rough) name=$mm ;;
  smooth|flat)
    [ "$storage" = compact ] || { echo "$0: the $ground ground is run on compact storage only, not '$storage'" >&2; exit 2; }
    name=$mm/$ground ;;
  *) echo "$0: the fifth argument is rough, smooth or flat, not '$ground'" >&2; exit 2 ;;
esac
case $what in
  find) run=FieldSearch toggle='*fieldSearch*' function='WheelContactFinder::find(' ;;
  step) run=FieldStep toggle='*fieldStep*' function='TyreModel::step(' ;;
  *) echo "$0: the fourth argument is find or step, not '$what'" >&2; exit 2 ;;
esac
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for t in 0.01 0.3; do
  valgrind --tool=callgrind --callgrind-out-file="$out/$t" --toggle-collect="$toggle" "$bench" \
    --benchmark_filter="$run/$storage/$name\$" --benchmark_min_time=$t >/dev/null 2>&1
done
# The function's inclusive count, and its calls (the counts on its
# callers' lines, just above it in the caller tree).
inclusive() {
  callgrind_annotate --inclusive=yes "$1" 2>/dev/null | awk -v f="$function" 'index($0, f) {gsub(",", "", $1); print $1; exit}'
}
calls() {
  callgrind_annotate --tree=caller --inclusive=yes "$1" 2>/dev/null |
    awk -v f="$function" '/^$/ {n = 0; next}
      /^ *[0-9,]+ .*  < / && match($0, /\(([0-9,]+)x\)/) {c = substr($0, RSTART + 1, RLENGTH - 3); gsub(",", "", c); n += c; next}
      /\*  / && index($0, f) {print n; exit}'
}
i1=$(inclusive "$out/0.01"); i2=$(inclusive "$out/0.3")
c1=$(calls "$out/0.01"); c2=$(calls "$out/0.3")
echo "$run/$storage/$name: $(( (i2 - i1) / (c2 - c1) )) instructions a $what ($(( c2 - c1 )) calls)"
