#!/bin/sh
# The robot on one rough surface sampled at 50, 5, 2 and 1 cm, in both
# engines (issue 53, item 6): the same continuous surface (long waves and a
# 0.15-0.8 m roughness, bench/make_rough_dem.py) written once as a 1 cm
# GeoTIFF and read with step 50, 5, 2, 1; robot_rough.yaml's drive on it
# for `duration` s. Prints µs a step, × real time and WTC's share of the
# step from each run's summary.json.
#   bench/rough_spacing_scene.sh [build dir] [output dir] [duration s]
set -eu
build=${1:-build}
out=${2:-runs/rough_spacing}
duration=${3:-4}
root=$(cd "$(dirname "$0")/.." && pwd)
# Debian's python3 (NumPy's and the build's package's), before any other on PATH.
python=${PYTHON:-$( [ -x /usr/bin/python3 ] && echo /usr/bin/python3 || echo python3)}
mkdir -p "$out"
PYTHONPATH="$build/python" "$python" "$root/bench/make_rough_dem.py" "$out/rough_1cm.tif"
for step in 50 5 2 1; do
  cat > "$out/rough_dem_s$step.yaml" <<YAML
description: bench/make_rough_dem.py's surface, 16 m x 6 m, from a 1 cm GeoTIFF, every ${step}th sample.
materials:
  compacted_soil: {mu_max: 0.6, s1: 0.1, s2: 0.3, rolling_resistance: 0.04}
pieces:
  - {type: heightfield, file: rough_1cm.tif, step: $step, translation: [-8, -3, 0], base_depth: 0.5,
     storage: compact}
YAML
  for engine in bullet ode; do
    name="s${step}_${engine}"
    rm -rf "${out:?}/$name"
    "$build/apps/wtc-sim" "$root/scenes/robot_rough.yaml" --engine "$engine" --no-plots --out "$out/$name" \
      --set "terrain=$(cd "$out" && pwd)/rough_dem_s$step.yaml" --set "duration=$duration" \
      --set "success.min_distance=0" >"$out/$name.log" 2>&1 || true
  done
done
"$python" - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
print("| cell | engine | µs a step | × real time | WTC's share | distance (m) |")
print("|---|---|---|---|---|---|")
for step in (50, 5, 2, 1):
    for engine in ("bullet", "ode"):
        path = os.path.join(out, f"s{step}_{engine}", "summary.json")
        if not os.path.exists(path):
            print(f"| {step} cm | {engine} | (no run) | | | |")
            continue
        s = json.load(open(path))
        print(f"| {step} cm | {engine} | {1e6 * s['wall_time'] / s['steps']:.1f} | {s['real_time_factor']:.2f} | "
              f"{100 * s['wtc_share']:.0f} % | {s['distance_m']:.2f} |")
PY
