#!/usr/bin/env bash
# Installs, from Debian 12 packages, whatever WTC needs and the machine lacks.
# Idempotent and quiet when everything is present (no apt-get update then).
set -euo pipefail
packages=(
  g++ cmake make pkg-config
  libeigen3-dev libqhull-dev                     # core: linear algebra, hulls
  libfcl-dev libccd-dev                          # independent distance checks
  libassimp-dev assimp-testmodels                # mesh import and its test files
  zlib1g-dev                                     # assimp's CMake config links libz.so; libassimp-dev lacks the dependency
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev
  libgdal-dev                                    # DEMs: GeoTIFF and the other rasters GDAL reads
  liburdfdom-dev libtinyxml-dev                  # vehicles from URDF (urdfdom, and the TinyXML it parses with)
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib                    # wtc-sim's figures
  python3-yaml                                  # tools/validation_table.py, tools/mobility_bounds.py
  python3-dev pybind11-dev python3-numpy python3-pytest  # the Python package wtc (python/) and its tests
  libjs-three chromium-headless-shell           # the replay page (three.js) and its test (headless Chromium)
  clang-14 libclang-rt-14-dev                   # libFuzzer, ASan, UBSan for fuzz/ (ctest -L fuzz)
  libtbb-dev parallel                           # the accuracy study: runs on all cores (TBB), or as a job list (GNU parallel)
  slurm-wlm munge   # the cluster test: a real Slurm on localhost (tests/study/slurm_cluster_test.sh)
)
# Each engine's own, listed in its folder (plugins/<engine>/debian-packages: names, '#' comments).
for list in "$(dirname "$0")"/../plugins/*/debian-packages; do
  [[ -f $list ]] || continue
  read -r -a own <<<"$(sed 's/#.*//' "$list" | tr '\n' ' ')"
  packages+=("${own[@]}")
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
