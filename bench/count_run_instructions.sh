#!/usr/bin/env bash
# Instructions of one `blayer extrude` run on one thread, in all and by phase: valgrind
# (callgrind) counts them, and each phase is the inclusive count of the function that
# does it. Unlike a time, the count does not move with the load of a shared machine,
# so two builds compare in one reading each (a run takes some 100 times as long as
# without valgrind: minutes for the generated CAD cases). Usage:
#   bench/count_run_instructions.sh [-b BUILD_DIR] SURFACE EXTRUDE_OPTION...
# e.g. SURFACE --layers 10 --first-height 0.0022 --growth-ratio 1.2 (--threads 1 is
# added; the mesh goes to a temporary directory). Needs valgrind
# (scripts/install-deps.sh --extras) and a built blayer-cli.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
if [[ "${1:-}" == "-b" ]]; then
  build="$2"
  shift 2
fi
[[ $# -ge 1 ]] || { echo "usage: $0 [-b BUILD_DIR] SURFACE EXTRUDE_OPTION..." >&2; exit 1; }
surface="$1"
shift
exe="$build/app/blayer-cli"
[[ -x "$exe" ]] || { echo "error: $exe not built" >&2; exit 1; }
command -v valgrind > /dev/null || { echo "error: valgrind not found (scripts/install-deps.sh --extras)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
valgrind --tool=callgrind --callgrind-out-file="$work/out" "$exe" extrude "$surface" -o "$work/mesh.vtu" "$@" \
  --threads 1 > "$work/stdout" 2> "$work/stderr" || { grep -v '^==' "$work/stderr" >&2; exit 1; }
total=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/stderr")
callgrind_annotate --inclusive=yes --threshold=100 "$work/out" > "$work/annotated"

# label, then the function whose inclusive count is the phase's (its name up to the
# opening parenthesis, as callgrind_annotate prints it); indented labels are parts of
# the phase above them.
phases=(
  "reading and checking the surface|blayer::load_surface"
  "march (all attempts)|blayer::(anonymous namespace)::march"
  "  front collisions|blayer::FrontChecker::check_intersections"
  "  new cells' validity|blayer::FrontChecker::check_cells"
  "  new cells' solver acceptance|blayer::FrontChecker::check_acceptance"
  "  proximity|blayer::limit_by_proximity"
  "  point normals|blayer::compute_vertex_normal"
  "  summary|blayer::summarise_extrusion"
  "final check of the mesh|blayer::check_volume_mesh"
  "writing|blayer::write_mesh_output"
)
grep -E "^(cells|check):" "$work/stdout" || true
printf "%-36s %16s %7s\n" "phase" "instructions" "share"
printf "%-36s %16s %7s\n" "run" "$total" "100.0%"
for entry in "${phases[@]}"; do
  label="${entry%%|*}"
  function="${entry#*|}"
  # callgrind_annotate sums a function's calls; the first line naming it is its own.
  count=$(awk -v f=":$function(" 'index($0, f) { gsub(",", "", $1); print $1; exit }' "$work/annotated")
  if [[ -z "$count" ]]; then
    printf "%-36s %16s\n" "$label" "not run"
  else
    printf "%-36s %16s %6.1f%%\n" "$label" "$count" "$(echo "100 * $count / $total" | bc -l)"
  fi
done
