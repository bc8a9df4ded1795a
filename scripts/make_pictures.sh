#!/usr/bin/env bash
# Renders the README's pictures (docs/images/*.png) headless: runs the cases and slices
# their meshes where users look first: a sharp trailing edge and a cube corner (with fans
# and with single columns), a concave junction and a thin slot. Needs the extras
# (python3-vtk9, xvfb): scripts/install-deps.sh --extras.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh" --extras
bash "$root/scripts/build.sh" blayer
out="$root/out/pictures"
mkdir -p "$out" "$root/docs/images"
blayer="$root/build/app/blayer"
render() { xvfb-run -a /usr/bin/python3 "$root/scripts/render_slice.py" "$@"; }

"$blayer" extrude --config "$root/cases/001_onera_m6_16k/case.toml" -o "$out/m6.vtu" >/dev/null
"$blayer" extrude --config "$root/cases/001_onera_m6_16k/case.toml" --fan-angle 0 -o "$out/m6_single.vtu" >/dev/null
"$blayer" extrude --config "$root/cases/014_cube_fans/case.toml" -o "$out/cube_fans.vtu" >/dev/null
"$blayer" extrude --config "$root/cases/003_cube/case.toml" -o "$out/cube_single.vtu" >/dev/null
"$blayer" extrude --config "$root/cases/005_cylinder_on_plate/case.toml" -o "$out/cylinder.vtu" >/dev/null
"$blayer" extrude --config "$root/cases/006_thin_slot/case.toml" -o "$out/slot.vtu" >/dev/null
"$blayer" extrude --config "$root/cases/013_onera_m6_half/case.toml" --fill -o "$out/m6_half.vtu" >/dev/null

render "$out/m6.vtu" "$root/docs/images/m6_trailing_edge.png" --origin 0.97 0.6 0 --normal 0 1 0 \
  --focus 0.96 0.6 0 --width 0.05 --title "ONERA M6, trailing edge at y = 0.6: 10 layers with a fan of columns, coloured by layer"
render "$out/m6_single.vtu" "$root/docs/images/m6_trailing_edge_single.png" --origin 0.97 0.6 0 --normal 0 1 0 \
  --focus 0.96 0.6 0 --width 0.05 --title "The same with one column per point (--fan-angle 0)"
render "$out/cube_fans.vtu" "$root/docs/images/cube_corner_fans.png" --origin 1 1 0.5 --normal 1 -1 0 \
  --focus 1 1 1 --width 0.35 --up 0 0 1 --title "Cube corner, slice x = y: fans of columns at the edges and the corner"
render "$out/cube_single.vtu" "$root/docs/images/cube_corner_single.png" --origin 1 1 0.5 --normal 1 -1 0 \
  --focus 1 1 1 --width 0.35 --up 0 0 1 --title "The same with one column per point (--fan-angle 0)"
render "$out/cylinder.vtu" "$root/docs/images/cylinder_plate_junction.png" --origin 0.5 0 0 --normal 0 -1 0 \
  --focus 0.58 0 0.07 --width 0.22 --title "Cylinder on plate, concave junction (slice y = 0), coloured by layer"
render "$out/slot.vtu" "$root/docs/images/thin_slot.png" --origin 1 0.5 0.5 --normal 0 -1 0 \
  --focus 1 0.5 0.36 --width 0.3 --title "Thin slot (0.1 wide, slice y = 0.5): fronts limited to under half the gap"
render "$out/m6_half.vtu" "$root/docs/images/m6_half_root.png" --origin 0.4 0.0000001 0 --normal 0 1 0 \
  --focus 0.75 0 0 --width 0.2 --up 0 0 1 \
  --title "ONERA M6 half model: layers and fill on the symmetry plane y = 0 (trailing edge)"
ls -la "$root/docs/images"
