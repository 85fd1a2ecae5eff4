#!/usr/bin/env bash
# Compares one benchmark between an earlier commit and the working tree, in alternating rounds.
#
#   scripts/compare-builds.sh BASE TARGET [benchmark options...]
#   scripts/compare-builds.sh HEAD~1 bench_exact_route --benchmark_filter='AllSixCapacities/1000$'
#
# BASE is built in a worktree under build-compare/ (Release, only TARGET and what it links), the
# working tree in ./build. Each round runs BASE's benchmark, then the working tree's, each with
# LD_LIBRARY_PATH on its own build's libplascap_*.so: the benchmarks find plascap's libraries through
# the RUNPATH of the tree they were built in, so a copied benchmark binary would run whatever library
# that tree holds now, and two copies would compare one library with itself. Prints each round's
# medians (ROUNDS, default 3; the options get --benchmark_repetitions=5 unless they set it). Run it
# on an otherwise idle machine: the benchmarks measure one core. The worktree stays for the next
# comparison with the same BASE; `git worktree remove build-compare/<commit>` deletes it.
set -euo pipefail
if [[ $# -lt 2 ]]; then
  sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
base=$1 target=$2
shift 2
cd "$(dirname "$0")/.."
root=$(pwd)
commit=$(git rev-parse --verify --quiet "$base^{commit}") || { echo "compare-builds: '$base' is not a commit" >&2; exit 2; }
rounds=${ROUNDS:-3}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "compare-builds: ROUNDS must be a positive integer, got '$rounds'" >&2; exit 2; }
options=("$@")
[[ " ${options[*]-} " == *"--benchmark_repetitions"* ]] || options+=(--benchmark_repetitions=5)
options+=(--benchmark_report_aggregates_only=true)

build_target() {  # source dir, build dir
  echo "compare-builds: building $target in $2" >&2
  cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$2" --target "$target" -j"$(nproc)" >/dev/null ||
    { echo "compare-builds: could not build $target in $2 (the benchmarks are the bench_* targets of bench/)" >&2; exit 2; }
  [[ -x $2/bench/$target ]] || { echo "compare-builds: $target is not a benchmark in bench/ of $2" >&2; exit 2; }
}

worktree=$root/build-compare/${commit:0:12}
if [[ ! -d $worktree ]]; then
  mkdir -p "$root/build-compare"
  git worktree add --detach --quiet "$worktree" "$commit"
fi
build_target "$worktree" "$worktree/build"
build_target "$root" "$root/build"

library_path() {  # the directories of a build's plascap libraries, ':'-separated
  find "$1" -name 'libplascap_*.so' -printf '%h\n' | sort -u | paste -sd: -
}

for round in $(seq "$rounds"); do
  for side in base work; do
    if [[ $side == base ]]; then dir=$worktree/build; label="${base} (${commit:0:9})"; else dir=$root/build; label="working tree"; fi
    echo "== round $round: $label"
    output=$(LD_LIBRARY_PATH=$(library_path "$dir") "$dir/bench/$target" "${options[@]}" 2>&1) || true
    if ! grep '_median' <<<"$output"; then
      echo "compare-builds: $target ($label) printed no medians:" >&2
      echo "$output" | tail -5 >&2
      exit 1
    fi
  done
done
