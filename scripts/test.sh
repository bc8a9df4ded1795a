#!/usr/bin/env bash
# Builds everything and runs the whole test suite through CTest.
#   scripts/test.sh [ctest args...]            the Release build in ./build
#   scripts/test.sh --checked [ctest args...]  the same suite on ./build-checked, with
#                                              the expensive internal checks on
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ "${1:-}" == "--checked" ]]; then
  shift
  bash "$root/scripts/build_checked.sh"
  ctest --test-dir "$root/build-checked" --output-on-failure -j "${BLAYER_JOBS:-2}" "$@"
  exit
fi
bash "$root/scripts/build.sh"
ctest --test-dir "$root/build" --output-on-failure -j "${BLAYER_JOBS:-2}" "$@"
