#!/usr/bin/env bash
# Same-run comparison of hybrid meshes (prism layers + tetrahedra to a farfield box)
# with Gmsh's extrude-then-tetrahedralise on one closed surface: wall time, peak memory,
# cell counts and blayer's check of both. Usage:
#   bench/compare_gmsh_hybrid.sh SURFACE.off[.gz] [layers=10] [ratio=1.2] [farfield_scale=10]
# The first height is 2e-4 x the bounding-box diagonal. Both farfields are the same box:
# centred on the surface's bounding box, each side farfield_scale x max(extent_k,
# extent_max / 2), blayer's default box (blayer measures it on the layers' envelope,
# which is 2 x the total thickness larger). Needs gmsh (scripts/install-deps.sh --extras)
# and a built blayer (scripts/build.sh blayer).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
surface="$1"; layers="${2:-10}"; ratio="${3:-1.2}"; scale="${4:-10}"
blayer="$root/build/app/blayer"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
name="$(basename "$surface")"; name="${name%%.*}"

/usr/bin/python3 "$root/bench/off_to_stl.py" "$surface" "$work/$name.stl"
/usr/bin/python3 - "$work/$name.stl" "$layers" "$ratio" "$scale" "$name" > "$work/$name.geo" 2> "$work/h1.txt" <<'PY'
import math, sys
path, n, r, scale, name = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
lo = [math.inf] * 3; hi = [-math.inf] * 3
for line in open(path):
    w = line.split()
    if w and w[0] == "vertex":
        for k in range(3):
            v = float(w[k + 1]); lo[k] = min(lo[k], v); hi[k] = max(hi[k], v)
h = 2e-4 * math.dist(lo, hi)
sys.stderr.write("%.9g\n" % h)
acc, heights = 0.0, []
for k in range(n):
    acc += h * r ** k
    heights.append("%.12g" % acc)
ext = [hi[k] - lo[k] for k in range(3)]
side = [scale * max(e, max(ext) / 2) for e in ext]
c = [(hi[k] + lo[k]) / 2 for k in range(3)]
b0 = [c[k] - side[k] / 2 for k in range(3)]
b1 = [c[k] + side[k] / 2 for k in range(3)]
lc = max(side) / 10
print('Merge "%s.stl";' % name)
print("out[] = Extrude { Surface{1}; Layers{ {%s}, {%s} }; Recombine; };" % (",".join(["1"] * n), ",".join(heights)))
pts = [(b0[0], b0[1], b0[2]), (b1[0], b0[1], b0[2]), (b1[0], b1[1], b0[2]), (b0[0], b1[1], b0[2]),
       (b0[0], b0[1], b1[2]), (b1[0], b0[1], b1[2]), (b1[0], b1[1], b1[2]), (b0[0], b1[1], b1[2])]
for i, p in enumerate(pts):
    print("Point(%d) = {%.12g, %.12g, %.12g, %.12g};" % (1001 + i, p[0], p[1], p[2], lc))
lines = [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (6, 7), (7, 8), (8, 5), (1, 5), (2, 6), (3, 7), (4, 8)]
for i, (a, b) in enumerate(lines):
    print("Line(%d) = {%d, %d};" % (2001 + i, 1000 + a, 1000 + b))
loops = [(1, 2, 3, 4), (5, 6, 7, 8), (1, 10, -5, -9), (2, 11, -6, -10), (3, 12, -7, -11), (4, 9, -8, -12)]
for i, l in enumerate(loops):
    ids = ",".join(("-" if x < 0 else "") + str(2000 + abs(x)) for x in l)
    print("Curve Loop(%d) = {%s}; Plane Surface(%d) = {%d};" % (3001 + i, ids, 4001 + i, 3001 + i))
print("Surface Loop(5001) = {4001:4006}; Surface Loop(5002) = {out[0]};")
print("Volume(6001) = {5001, 5002};")
PY
h1=$(cat "$work/h1.txt")

source "$root/bench/measure.sh"

echo "surface $surface: N=$layers h1=$h1 r=$ratio farfield scale $scale"
(cd "$work" && measure gmsh gmsh "$name.geo" -3 -format vtk -o "$work/gmsh.vtk")
measure blayer "$blayer" extrude "$surface" -o "$work/blayer.vtu" --layers "$layers" --first-height "$h1" \
  --growth-ratio "$ratio" --fill --farfield-scale "$scale"
echo "ratio blayer/gmsh wall time: $(ratio blayer gmsh)"
echo "ratio blayer/gmsh CPU time: $(ratio blayer gmsh cpu)"
echo "ratio blayer/gmsh peak memory: $(memory_ratio blayer gmsh)"
for m in gmsh.vtk blayer.vtu; do
  echo "--- blayer check of ${m%%.*}'s mesh:"
  "$blayer" check "$work/$m" | grep -E "^(cells:|inverted:|min_corner|faces:)" || true
done
grep -E "tets|^coverage" "$work/blayer.log" || true
