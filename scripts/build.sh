#!/usr/bin/env bash
# Installs the dependencies (if missing), configures and builds blayer in ./build.
# Usage: scripts/build.sh [cmake targets...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
jobs="${BLAYER_JOBS:-2}"
if [[ ! -f "$root/build/build.ninja" ]]; then
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
if (($# > 0)); then
  cmake --build "$root/build" -j "$jobs" --target "$@"
else
  cmake --build "$root/build" -j "$jobs"
fi
