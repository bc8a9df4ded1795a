#!/usr/bin/env bash
# Same-run comparison of a half model with its mirrored full model (issue of symmetry
# planes: the half's cells should be about half the full's): both with the same law
# (N = 10, h1 = 2e-4 x the full model's diagonal, r = 1.2), layers only and with --fill;
# the fill is run at three farfield scales (10, 10.001, 9.999), since TetGen's cell
# count moves by a few per cent with any change of its input. Usage:
#   bench/compare_half_full.sh HALF.off[.gz] AXIS     (AXIS: x, y or z; the plane AXIS = 0)
# Needs a built blayer (scripts/build.sh blayer).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
half="$1"; axis="$2"
blayer="$root/build/app/blayer"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$root/bench/mirror_half_model.py" "$half" "$axis" "$work/full.off"
h1=$(/usr/bin/python3 - "$work/full.off" <<'PY'
import math, sys
w = open(sys.argv[1]).read().split()
nv = int(w[1]); p = [float(x) for x in w[4:4 + 3 * nv]]
lo = [min(p[k::3]) for k in range(3)]; hi = [max(p[k::3]) for k in range(3)]
print("%.12g" % (2e-4 * math.dist(lo, hi)))
PY
)
law=(--layers 10 --first-height "$h1" --growth-ratio 1.2)
cells() { grep -E "^check:" "$1" | sed -E 's/^check: ([0-9]+) cells.*/\1/'; }
# Both models with the same options; prints both cell counts and their ratio.
compare() {
  local label="$1"; shift
  "$blayer" extrude "$half" -o "$work/h.vtu" "${law[@]}" "$@" > "$work/h.log" 2>&1
  "$blayer" extrude "$work/full.off" -o "$work/f.vtu" "${law[@]}" "$@" > "$work/f.log" 2>&1
  local nh nf
  nh=$(cells "$work/h.log"); nf=$(cells "$work/f.log")
  echo "$label: half $nh, full $nf cells, ratio $(/usr/bin/python3 -c "print('%.4f' % ($nh / $nf))")"
}
echo "half $half, plane $axis = 0, h1 = $h1"
compare "layers only"
for scale in 10 10.001 9.999; do
  compare "fill, farfield scale $scale" --fill --farfield-scale "$scale"
done
