#!/usr/bin/env bash
# Regenerates the coupled yield surface's figures and report in docs/: the onset of flow and the
# flow error against dt on every engine (coupled-yield-report.md, coupled-yield-error.svg, by
# adapter-report --coupled and gnuplot), and the interaction diagrams of an IPE 300 with the box of
# independent limits (yield-surface-ipe300.svg, by section-calc). A few seconds after the build.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gnuplot > /dev/null || { echo "coupled-yield-report: installing gnuplot-nox" >&2; apt-get install -y -qq gnuplot-nox > /dev/null; }
bash scripts/build.sh > /dev/null
data=$(mktemp)
trap 'rm -f "$data"' EXIT
build/tools/adapter-report/adapter-report --coupled docs/coupled-yield-report.md --plot-data "$data"
gnuplot -e "data='$data'; output='docs/coupled-yield-error.svg'" scripts/coupled-yield-report.gp
build/tools/section-calc/section-calc --shape "IPE 300" --material S355 --load N=4e5,Mx=1.5e5,Mz=1e4 \
  --interaction --svg docs/yield-surface-ipe300.svg > /dev/null
echo "coupled-yield-report: wrote docs/coupled-yield-report.md, docs/coupled-yield-error.svg, docs/yield-surface-ipe300.svg" >&2
