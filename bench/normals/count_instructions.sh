#!/usr/bin/env bash
# Instructions of the default most-normal solver per fan, on most_normal_bench's generated
# fans: valgrind (callgrind) counts what most_normal_solve_once executes while it solves
# a set, and nothing else. Unlike a time, the count does not move with the load of a
# shared machine, so two builds compare in one reading each; the digest of the answers
# says whether they differ. Usage:
#   bench/normals/count_instructions.sh [-b BUILD_DIR] [SET ...]
# SET: a valence k or shape/k, as most_normal_solve_once takes it (default: 20 40 60).
# Needs valgrind (scripts/install-deps.sh --extras) and a built most_normal_solve_once
# (ninja -C build bench/normals/most_normal_solve_once).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$root/build"
if [[ "${1:-}" == "-b" ]]; then
  build="$2"
  shift 2
fi
sets=("$@")
[[ ${#sets[@]} -gt 0 ]] || sets=(20 40 60)
exe="$build/bench/normals/most_normal_solve_once"
[[ -x "$exe" ]] || { echo "error: $exe not built" >&2; exit 1; }
command -v valgrind > /dev/null || { echo "error: valgrind not found (scripts/install-deps.sh --extras)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for set in "${sets[@]}"; do
  valgrind --tool=callgrind --toggle-collect='*solve_set*' --callgrind-out-file="$work/out" "$exe" "$set" \
    > "$work/stdout" 2> "$work/stderr" || { cat "$work/stderr" >&2; exit 1; }
  instructions=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/stderr")
  fans=$(sed -n 's/^set [^:]*: \([0-9]*\) fans.*/\1/p' "$work/stdout")
  echo "$(cat "$work/stdout"); instructions $instructions ($((instructions / fans)) per fan)"
done
