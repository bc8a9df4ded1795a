#!/usr/bin/env bash
# The main job on the bundled default case: ten prism layers on the ONERA M6 wing
# (16k triangles, sharp trailing edge), written to out/onera_m6_layers.vtu.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh" blayer
mkdir -p "$root/out"
"$root/build/app/blayer" extrude --config "$root/cases/001_onera_m6_16k/case.toml" \
  -o "$root/out/onera_m6_layers.vtu" --envelope "$root/out/onera_m6_envelope.vtp" \
  --report "$root/out/onera_m6_report.json"
echo
echo "Open it in ParaView: paraview $root/out/onera_m6_layers.vtu"
echo "  (colour by 'layer' or 'min_corner_jacobian'; Clip or Extract Cells By Region to see inside)"
