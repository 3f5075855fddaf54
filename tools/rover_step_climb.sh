#!/usr/bin/env bash
# The tallest step the rocker-bogie rover climbs with a plain drive-forward
# controller (scenes/rover_step.yaml), found by bisection to 1 cm at each
# friction level given, in one engine and mode (issue 37, item 4;
# docs/rocker-bogie-rover.md has the results beside the published claim).
#
# usage: tools/rover_step_climb.sh BUILD_DIR [ENGINE [MODE [MU...]]]
#   defaults: bullet force 0.5 1.0
# A height climbs when the run succeeds: every wheel ends above the step's
# top with the chassis tilted under 45 deg (the scene's success criteria).
set -euo pipefail
build=${1:?usage: tools/rover_step_climb.sh BUILD_DIR [ENGINE [MODE [MU...]]]}
engine=${2:-bullet}
mode=${3:-force}
shift $(($# < 3 ? $# : 3))
mus=("$@")
((${#mus[@]})) || mus=(0.5 1.0)
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

climbs() {  # $1 mu, $2 height (m): exit 0 when the rover climbs it
  local out="$scratch/run_$1_$2"
  "$build/apps/wtc-sim" "$root/scenes/rover_step.yaml" --engine "$engine" --mode "$mode" \
    --set "mu=$1" --set "step_height=$2" --out "$out" --quiet --no-plots --no-replay >/dev/null 2>&1 || true
  python3 -c 'import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))["success"] else 1)' "$out/summary.json"
}

for mu in "${mus[@]}"; do
  lo=0.00   # climbed (a flat ground)
  hi=0.40   # 4 r, the claim's twice the diameter: assumed not climbed, checked below
  if climbs "$mu" "$hi"; then echo "mu $mu: climbs $hi m, the top of the search"; continue; fi
  while python3 -c "import sys; sys.exit(0 if $hi - $lo > 0.01 + 1e-9 else 1)"; do
    mid=$(python3 -c "print(round(($lo + $hi) / 2, 4))")
    if climbs "$mu" "$mid"; then lo=$mid; else hi=$mid; fi
    echo "mu $mu: $mid m $( [ "$lo" = "$mid" ] && echo climbed || echo not climbed)" >&2
  done
  echo "mu $mu ($engine, $mode): climbs $lo m, not $hi m (wheel radius 0.10 m: $(python3 -c "print(round($lo / 0.1, 2))") r)"
done
