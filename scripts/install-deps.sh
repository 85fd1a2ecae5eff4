#!/usr/bin/env bash
# Installs every Debian 12 package plascap builds, tests or benchmarks with.
# Idempotent: packages already present are left as they are.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libcgal-dev libgmp-dev libmpfr-dev   # exact geometry (validation, meshing)
  libgsl-dev                           # cubature
  libeigen3-dev                        # linear algebra
  libboost-dev                         # Boost.Geometry R-tree (sand-heap distances)
  libbullet-dev                        # Bullet 3.24, float and float64 builds
  libode-dev                           # ODE 0.16, double precision
  libgtest-dev libgmock-dev            # tests
  libbenchmark-dev                     # benchmarks
  libcli11-dev                         # command-line options
  nlohmann-json3-dev                   # JSON files
  pybind11-dev python3-dev python3-pytest  # the Python module and its tests (Debian's /usr/bin/python3)
  python3-numpy python3-distributed python3-pandas  # its arrays, sweeps on dask, tables
  libjs-three libjs-chart.js           # three.js and Chart.js, inlined into the --html pages
  chromium python3-pil                 # the pages' tests: headless Chromium, and PIL for their screenshots
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq "${missing[@]}" >/dev/null
echo "install-deps: done"
