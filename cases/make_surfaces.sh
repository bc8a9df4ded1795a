#!/usr/bin/env bash
# Regenerates the generated case surfaces (surface.stl) from their surface.geo with gmsh
# (Debian package gmsh, installed by scripts/install-deps.sh --extras). The STL files are
# committed, so running the cases needs no gmsh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
for geo in */surface.geo; do
  dir=$(dirname "$geo")
  gmsh "$geo" -2 -format stl -o "$dir/surface.stl" >/dev/null
  echo "$dir/surface.stl"
done
