#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer and UndefinedBehaviorSanitizer in
# ./build-sanitized and runs it: out-of-bounds accesses, use after free, leaks and
# undefined behaviour in blayer's code (and in what it hands to VTK, TetGen and TBB)
# fail the tests they occur in. RelWithDebInfo, benchmarks left out: timings mean
# nothing under the sanitizers. .ci/run runs it after the plain suite.
# Usage: scripts/test_sanitized.sh [ctest args...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
jobs="${BLAYER_JOBS:-2}"
build="$root/build-sanitized"
# UBSan checks stay recoverable at compile time so that the few reports listed in
# scripts/ubsan-suppressions.txt can be suppressed; halt_on_error below makes every
# other one fatal.
flags="-fsanitize=address,undefined -fno-omit-frame-pointer"
if [[ ! -f "$build/build.ninja" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBLAYER_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" >/dev/null
fi
cmake --build "$build" -j "$jobs"
# halt_on_error / abort_on_error: the first report fails the test. detect_leaks: the
# whole test process is checked for leaks at exit. handle_segv=0: a segfault kills the
# process with SIGSEGV as in a normal build (the fill's crash-isolation tests kill a
# child that way on purpose and check the signal; ASan's handler would abort instead).
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=1:handle_segv=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$root/scripts/ubsan-suppressions.txt"
ctest --test-dir "$build" --output-on-failure -j "$jobs" "$@"
