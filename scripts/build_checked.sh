#!/usr/bin/env bash
# Builds blayer in ./build-checked with the expensive internal checks compiled in
# (-DBLAYER_EXPENSIVE_CHECKS=ON, see core/include/blayer/core/assert.h), RelWithDebInfo
# so that a failed check has a usable stack in a debugger. Benchmarks are left out:
# their timings mean nothing with the checks on.
# Usage: scripts/build_checked.sh [cmake targets...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
jobs="${BLAYER_JOBS:-2}"
build="$root/build-checked"
if [[ ! -f "$build/build.ninja" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DBLAYER_EXPENSIVE_CHECKS=ON -DBLAYER_BUILD_BENCH=OFF >/dev/null
fi
if (($# > 0)); then
  cmake --build "$build" -j "$jobs" --target "$@"
else
  cmake --build "$build" -j "$jobs"
fi
