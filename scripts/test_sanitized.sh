#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer and UndefinedBehaviorSanitizer in
# ./build-sanitized and runs it: out-of-bounds accesses, use after free, leaks and
# undefined behaviour in blayer's code (and in what it hands to VTK, TetGen and TBB)
# fail the tests they occur in. Benchmarks left out: timings mean nothing under the
# sanitizers. .ci/run runs it after the plain suite.
#
# Cost: .ci/run must stay well under 30 minutes on a 2-core machine, and this build is
# most of it. -O1 -g1 (line tables only, which is all a sanitizer's stack trace needs)
# instead of RelWithDebInfo's -O2 -g compiles about 45 % faster (a test TU: 16 s
# against 29 s) with the same checks; the tests run a little slower, and they are the
# smaller part. NDEBUG as in the release build, so the suite tests the same code.
# The tests' own sources compile at -O0 (BLAYER_TEST_CODE_FLAGS; the code they test
# keeps -O1): their 87 objects build in about 4 minutes instead of 10 on two cores, and
# the suite runs no slower, since the few sources whose own code is heavy (the sampling
# oracle) keep the build's flags (KEEP_BUILD_FLAGS in tests/).
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
# Configured on every run (quick once configured, and no rebuild when nothing changed),
# so that a build directory configured by an older version of this script cannot keep
# other flags.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBLAYER_BUILD_BENCH=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DBLAYER_TEST_CODE_FLAGS=-O0 \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" \
  -DCMAKE_MODULE_LINKER_FLAGS="$flags" >/dev/null
cmake --build "$build" -j "$jobs"
# halt_on_error / abort_on_error: the first report fails the test. detect_leaks: the
# whole test process is checked for leaks at exit. handle_segv=0: a segfault kills the
# process with SIGSEGV as in a normal build (the fill's crash-isolation tests kill a
# child that way on purpose and check the signal; ASan's handler would abort instead).
# allocator_may_return_null: malloc returns null for a request too large to satisfy
# instead of aborting (VTK sizes a .vtp's connectivity from the offsets it reads with
# malloc and reports a failed one as an error). The .vtp files whose counts or headers
# claim more memory than exists run here too: the reader refuses them before VTK would
# allocate (ASan's operator new reports such a request instead of throwing); under ASan the readers run in the
# test's own process (io/src/parse_in_child.cpp).
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=1:handle_segv=0:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$root/scripts/ubsan-suppressions.txt"
# Left out under the sanitizers (BLAYER_SANITIZE_ALL=1 runs them too):
#   PointNormals.ParallelRunIsDeterministic: 7.4 minutes alone under ASan+UBSan at -O1
#   (about 1 minute in the release build), longer than the rest of the suite takes on
#   two cores (about 6 minutes), so the suite's time was this one test's. It runs the
#   most-normal solver twice on a 2400-point uv sphere (60-triangle fans at the poles)
#   and compares the runs; the plain suite checks that agreement, and the solver's code
#   runs under the sanitizers in the normals' other tests (random, CAD-like and oracle
#   fans).
exclude=()
if [[ "${BLAYER_SANITIZE_ALL:-0}" != 1 ]]; then
  exclude=(-E '^PointNormals\.ParallelRunIsDeterministic$')
fi
# --timeout: a test that hangs (a forked child waiting on a lock the fork copied, say)
# fails after 15 minutes instead of holding the run (far above any test left in here).
ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 900 "${exclude[@]}" "$@"
