#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in ./build-fuzz, and runs each for SECONDS (default 60),
# one after the other (each fuzzer uses one core). Each starts from its seed corpus
# (fuzz/corpus/TARGET, read only) plus what earlier runs found (build-fuzz/corpus/TARGET).
# A crash, a sanitizer report, a leak or an input taking over 10 s stops that target
# and is saved under build-fuzz/findings/TARGET/; turn each into a regression test.
# Usage: scripts/fuzz.sh [seconds per target] [target...]   (targets: see fuzz/CMakeLists.txt)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh" --fuzz
build="$root/build-fuzz"
if [[ ! -f "$build/build.ninja" ]]; then
  cmake -S "$root/fuzz" -B "$build" -G Ninja -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 >/dev/null
fi
cmake --build "$build" -j "${BLAYER_JOBS:-2}" --target fuzzers

seconds="${1:-60}"
(($# > 0)) && shift
targets=("$@")
if ((${#targets[@]} == 0)); then
  targets=(read_stl_ascii read_stl_binary read_obj read_off read_ply_ascii read_ply_binary read_vtp read_vtk_legacy
           prepare_surface normals_fan extrude_check)
fi

# allocator_may_return_null=1: malloc returns null for an allocation too large to
# satisfy, instead of ASan aborting; VTK sizes a .vtp's connectivity from the offsets it
# reads (data no precheck sees) with malloc and reports a null as an error. (ASan's
# operator new still reports such a request: the VTP reader refuses the counts and
# headers that would make VTK ask, see io/src/vtk_module/vtp_precheck.h.)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export ASAN_SYMBOLIZER_PATH="$(command -v llvm-symbolizer-14 || true)"
mkdir -p "$build/logs"
failed=0
printf '%-18s %12s %10s %s\n' target executions exec/s result
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/findings/$t"
  log="$build/logs/$t.log"
  status=0
  before="$(find "$build/findings/$t" -type f | wc -l)"
  # VTK sizes a .vtp's connectivity from its (possibly corrupt) offsets with malloc;
  # a large request that the system grants lazily is harmless (the reader then finds
  # the data missing and blayer refuses the file), so for the VTP target only resident
  # memory is limited, not the size of one allocation.
  malloc_limit=()
  [[ "$t" == read_vtp ]] && malloc_limit=(-malloc_limit_mb=1048576)
  "$build/${t}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 "${malloc_limit[@]}" -print_final_stats=1 \
    -artifact_prefix="$build/findings/$t/" "$build/corpus/$t" "$root/fuzz/corpus/$t" >"$log" 2>&1 || status=$?
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
  rate="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)"
  result="ok"
  # A finding in a child process (any the code under test starts) does not stop the
  # parent:
  # count what was saved during the run as well as the exit status.
  new_files=$(( $(find "$build/findings/$t" -type f | wc -l) - before ))
  if ((status == 0 && new_files > 0)); then
    result="FINDINGS in child processes: $new_files new files in $build/findings/$t, see $log"
    failed=1
  fi
  if ((status != 0)); then
    result="FINDING (exit $status): $(ls -t "$build/findings/$t" | head -1), see $log"
    failed=1
  fi
  printf '%-18s %12s %10s %s\n' "$t" "${execs:-?}" "${rate:-?}" "$result"
done
exit "$failed"
