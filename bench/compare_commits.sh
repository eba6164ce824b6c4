#!/usr/bin/env bash
# Side-by-side benchmark of two commits in one run on one machine, as the project measures speed:
#   bench/compare_commits.sh [-n ROUNDS] [-o DIR] OLD_REV NEW_REV BENCH [ARGS...]
# builds BENCH (a target of bench/, e.g. bench_stress_update or mpm_bench) at both commits in
# scratch worktrees, then runs old and new alternately ROUNDS times (default 3), so drifts of the
# machine's load hit both alike. Every run's output goes to DIR/<round>_<old|new>.txt (default
# DIR: bench/results/compare); the outputs are printed one after the other for reading.
set -euo pipefail
rounds=3
out=""
while getopts "n:o:" opt; do
  case $opt in
    n) rounds=$OPTARG ;;
    o) out=$OPTARG ;;
    *) echo "usage: $0 [-n ROUNDS] [-o DIR] OLD_REV NEW_REV BENCH [ARGS...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
if (($# < 3)); then
  echo "usage: $0 [-n ROUNDS] [-o DIR] OLD_REV NEW_REV BENCH [ARGS...]" >&2
  exit 2
fi
old=$1 new=$2 bench=$3
shift 3
root=$(git rev-parse --show-toplevel)
out=${out:-$root/bench/results/compare}
mkdir -p "$out"
scratch=${TMPDIR:-/tmp}/acst-compare
build_rev() {  # build_rev REV -> prints the benchmark's path
  local sha
  sha=$(git -C "$root" rev-parse --short=12 "$1^{commit}")
  local tree=$scratch/$sha
  if [ ! -d "$tree" ]; then git -C "$root" worktree add --detach "$tree" "$sha" >/dev/null 2>&1; fi
  cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release -DACST_BUILD_TESTS=OFF >/dev/null
  cmake --build "$tree/build" -j "$(nproc)" --target "$bench" >/dev/null
  find "$tree/build/bench" -maxdepth 1 -type f -name "$bench" -perm -u+x | head -n 1
}
old_bin=$(build_rev "$old")
new_bin=$(build_rev "$new")
echo "old: $old ($old_bin)"
echo "new: $new ($new_bin)"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; $(date -u +%Y-%m-%dT%H:%MZ)"
for ((k = 1; k <= rounds; ++k)); do
  for side in old new; do
    bin=${side}_bin
    "${!bin}" "$@" >"$out/${k}_${side}.txt"
    echo "=== round $k, $side ==="
    cat "$out/${k}_${side}.txt"
  done
done
