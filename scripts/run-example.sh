#!/usr/bin/env bash
# README command 1: install, build, and print the capacities of the paper's 10 mm square.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/tools/section-calc/section-calc sections/examples/paper-square.json
