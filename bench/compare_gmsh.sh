#!/usr/bin/env bash
# Same-run comparison with Gmsh's plain boundary-layer extrusion (no collision, inversion
# or corner handling) on one surface: wall time and peak memory of both, blayer's check of
# both meshes, and the layer fidelity of both (first height against h1 and thickness
# against T per column, above the wall planes and as distance to the wall: blayer check
# --wall). Both mesh the same STL, so their wall points agree to the bit. Usage:
#   [BENCH_REPEAT=n] bench/compare_gmsh.sh SURFACE.off[.gz] [layers=10] [ratio=1.2]
# With BENCH_REPEAT the two run alternately n times and the ratio compares the fastest
# run of each (one run by default).
# The first height is 2e-4 x the bounding-box diagonal. Needs gmsh
# (scripts/install-deps.sh --extras) and a built blayer (scripts/build.sh blayer).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
surface="$1"; layers="${2:-10}"; ratio="${3:-1.2}"
blayer="$root/build/app/blayer"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
name="$(basename "$surface")"; name="${name%%.*}"

/usr/bin/python3 "$root/bench/off_to_stl.py" "$surface" "$work/$name.stl"
h1=$(/usr/bin/python3 - "$work/$name.stl" <<'PY'
import sys, math
lo = [math.inf] * 3; hi = [-math.inf] * 3
for line in open(sys.argv[1]):
    w = line.split()
    if w and w[0] == "vertex":
        for k in range(3):
            v = float(w[k + 1]); lo[k] = min(lo[k], v); hi[k] = max(hi[k], v)
print("%.9g" % (2e-4 * math.dist(lo, hi)))
PY
)
/usr/bin/python3 - "$name" "$layers" "$ratio" "$h1" > "$work/$name.geo" <<'PY'
import sys
name, n, r, h = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
acc, heights = 0.0, []
for k in range(n):
    acc += h * r ** k
    heights.append("%.12g" % acc)
print('Merge "%s.stl";' % name)
print("Extrude { Surface{1}; Layers{ {%s}, {%s} }; Recombine; }" % (",".join(["1"] * n), ",".join(heights)))
PY

source "$root/bench/measure.sh"

echo "surface $surface: N=$layers h1=$h1 r=$ratio"
for ((run = 0; run < ${BENCH_REPEAT:-1}; ++run)); do
  (cd "$work" && measure gmsh gmsh "$name.geo" -3 -format vtk -o "$work/gmsh.vtk")
  measure blayer "$blayer" extrude "$work/$name.stl" -o "$work/blayer.vtu" --layers "$layers" --first-height "$h1" \
    --growth-ratio "$ratio" ${BLAYER_ARGS:-}
done
echo "ratio blayer/gmsh wall time (fastest runs: $(cat "$work/blayer.secs") s / $(cat "$work/gmsh.secs") s): $(ratio blayer gmsh)"
echo "ratio blayer/gmsh CPU time (least of the runs: $(cat "$work/blayer.cpu") s / $(cat "$work/gmsh.cpu") s): $(ratio blayer gmsh cpu)"
echo "ratio blayer/gmsh peak memory (largest runs): $(memory_ratio blayer gmsh)"
law=(--wall "$work/$name.stl" --layers "$layers" --first-height "$h1" --growth-ratio "$ratio")
echo "--- blayer check of Gmsh's mesh:"
"$blayer" check "$work/gmsh.vtk" "${law[@]}" > "$work/gmsh.check" 2>&1 || true
grep -E "^(cells:|inverted:|min_corner|  fidelity|    )" "$work/gmsh.check" || true
echo "--- blayer check of blayer's mesh:"
"$blayer" check "$work/blayer.vtu" "${law[@]}" > "$work/blayer.check" 2>&1 || true
grep -E "^(cells:|inverted:|min_corner|  time:|  fidelity|    )" "$work/blayer.check" || true
grep -E "^(coverage|columns|time)" "$work/blayer.log" || true
# Fans at sharp edges (--fan-angle) give blayer several columns per ridge point, and so
# more cells than Gmsh's one column per point: the work per delivered cell compares them
# where the cell counts differ.
cells_b=$(awk '/^cells:/ {print $2; exit}' "$work/blayer.check")
cells_g=$(awk '/^cells:/ {print $2; exit}' "$work/gmsh.check")
cpu_b=$(cat "$work/blayer.cpu"); cpu_g=$(cat "$work/gmsh.cpu")
if [[ -n "$cells_b" && -n "$cells_g" ]] && [ "$(echo "$cpu_b > 0 && $cpu_g > 0" | bc -l)" = 1 ]; then
  per_b=$(echo "$cells_b / $cpu_b" | bc -l)
  per_g=$(echo "$cells_g / $cpu_g" | bc -l)
  printf "cells per CPU second (cells over the least CPU time): blayer %.0f (%s cells), gmsh %.0f (%s cells); ratio blayer/gmsh %.3f\n" \
    "$per_b" "$cells_b" "$per_g" "$cells_g" "$(echo "$per_b / $per_g" | bc -l)"
fi
