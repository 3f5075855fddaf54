#!/bin/sh
# The ledge climb's robustness table (issue 14): heights x engines x contact
# modes, then approach speeds and yaw misalignments, one wtc-sim run each;
# prints a Markdown table from each run's summary.json.
#   bench/ledge_climb_matrix.sh [build dir] [output dir]
set -eu
build=${1:-build}
out=${2:-runs/ledge_matrix}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
run() {  # name, then wtc-sim arguments
  name=$1; shift
  rm -rf "${out:?}/$name"
  "$build/apps/wtc-sim" "$root/scenes/robot_ledge.yaml" --out "$out/$name" --no-plots "$@" >/dev/null 2>&1 || true
}
for h in 0.20 0.40 0.55 0.60 0.65 0.70 0.80; do
  for engine in bullet ode; do
    for mode in force constraint; do
      run "h${h}_${engine}_${mode}" --engine $engine --mode $mode --set ledge_height=$h
    done
  done
done
for v in 0.2 0.8; do
  for engine in bullet ode; do run "v${v}_${engine}" --engine $engine --set approach_speed=$v --set ledge_height=0.65; done
done
for yaw in -5 5; do
  for engine in bullet ode; do run "yaw${yaw}_${engine}" --engine $engine --set yaw_deg=$yaw --set ledge_height=0.65; done
done
python3 "$root/bench/ledge_climb_table.py" "$out"
