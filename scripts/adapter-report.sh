#!/usr/bin/env bash
# Regenerates docs/<engine>-report.md and docs/<engine>-stability-map.csv: the adapter against the
# paper's Tables 3.5/3.6, the oscillator's accuracy against ω·dt, the stability map over stiffness,
# mass ratio, time step and iterations, and Charpy against the time step. Takes about a minute.
# Usage: scripts/adapter-report.sh [bullet]
set -euo pipefail
cd "$(dirname "$0")/.."
engine="${1:-bullet}"
./scripts/build.sh >/dev/null
./build/tools/adapter-report/adapter-report --engine "$engine" --scenes examples/scenes \
  --markdown "docs/$engine-report.md" --csv "docs/$engine-stability-map.csv"
echo "adapter-report: wrote docs/$engine-report.md and docs/$engine-stability-map.csv"
