#!/usr/bin/env bash
# Installs the dependencies (if missing), configures and builds blayer in ./build.
# Usage: scripts/build.sh [cmake targets...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
jobs="${BLAYER_JOBS:-2}"
if [[ ! -f "$root/build/build.ninja" ]]; then
  # The tests' own sources at -O0 (the libraries, the CLI and the benchmarks keep
  # Release's flags): they compile twice as fast, and the suite's time does not change.
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBLAYER_TEST_CODE_FLAGS=-O0 >/dev/null
fi
if (($# > 0)); then
  cmake --build "$root/build" -j "$jobs" --target "$@"
else
  cmake --build "$root/build" -j "$jobs"
fi
