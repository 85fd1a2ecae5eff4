#!/usr/bin/env bash
# Regenerates the adapter reports in docs/: for each engine, <engine>-report.md and
# <engine>-stability-map.csv (the paper's Tables 3.5/3.6, the oscillator's accuracy against ω·dt,
# the stability map over stiffness, mass ratio, time step and iterations, Charpy against the time
# step); and cross-engine.md (every example scene on every engine). A few minutes.
# Usage: scripts/adapter-report.sh [ENGINE...]   (default: bullet ode)
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh >/dev/null
report=./build/tools/adapter-report/adapter-report
engines=("$@")
[ ${#engines[@]} -gt 0 ] || engines=(bullet ode)
for engine in "${engines[@]}"; do
  "$report" --engine "$engine" --scenes examples/scenes \
    --markdown "docs/$engine-report.md" --csv "docs/$engine-stability-map.csv"
  echo "adapter-report: wrote docs/$engine-report.md and docs/$engine-stability-map.csv"
done
"$report" --scenes examples/scenes --cross-engine docs/cross-engine.md
echo "adapter-report: wrote docs/cross-engine.md"
