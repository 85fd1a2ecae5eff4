#!/usr/bin/env bash
# Regenerates docs/cubature-report.{md,csv,svg}: the cubature route's error against run time on six
# sections, with the mesh conforming to the kinks and without (tools/cubature-report), plotted by
# gnuplot. Takes about 10 s after the build. Timings are of this machine: run on an idle one.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gnuplot > /dev/null || { echo "cubature-report: installing gnuplot-nox" >&2; apt-get install -y -qq gnuplot-nox > /dev/null; }
bash scripts/build.sh > /dev/null
data=$(mktemp)
trap 'rm -f "$data"' EXIT
build/tools/cubature-report/cubature-report --csv docs/cubature-report.csv --markdown docs/cubature-report.md --plot-data "$data"
gnuplot -e "data='$data'; output='docs/cubature-report.svg'" scripts/cubature-report.gp
echo "cubature-report: wrote docs/cubature-report.md, docs/cubature-report.csv and docs/cubature-report.svg" >&2
