#!/usr/bin/env bash
# Re-derives the golden figures of the regression cases: runs each case (all, or those
# named: 002, 002_sphere, ...) and writes cases/NNN_name/expected.toml.new beside its
# expected.toml, with every figure's value replaced by the measured one and its operator,
# tolerance and comment kept. Nothing is overwritten: diff, check every change against
# the reason written next to the figure, then rename (cases/README.md).
# Every measured number of each case is written to build/golden-measured/NNN_name.json,
# to choose new figures from.
# Usage: scripts/update-golden.sh [case...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh" blayer case_tests >/dev/null
filter="Regression.*"
if (($# > 0)); then
  filter=""
  for c in "$@"; do
    name="$(basename "$c")"
    [[ -d "$root/cases/$name" ]] || ls -d "$root/cases/${name}"_* >/dev/null 2>&1 ||
      { echo "update-golden: no case folder cases/$name or cases/${name}_*" >&2; exit 1; }
    filter+="${filter:+:}Regression.${name}*"
  done
fi
measured="$root/build/golden-measured"
mkdir -p "$measured"
BLAYER_UPDATE_GOLDEN=1 BLAYER_MEASURED_DIR="$measured" \
  "$root/build/tests/cases/case_tests" --gtest_filter="$filter"
echo
echo "review with:"
for f in "$root"/cases/*/expected.toml.new; do
  [[ -e "$f" ]] && echo "  diff ${f%.new} $f"
done
echo "then: mv expected.toml.new expected.toml in each case you accept"
