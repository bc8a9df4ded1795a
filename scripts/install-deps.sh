#!/usr/bin/env bash
# Installs the Debian 12 packages blayer needs to build and test. Idempotent: packages
# already present are skipped, and nothing is fetched when all are there.
# Usage: scripts/install-deps.sh [--extras] [--fuzz]
#   --extras: the picture, timing and instruction-counting tools
#   --fuzz:   clang with libFuzzer and the sanitizer runtimes, and llvm-symbolizer for
#             readable reports (scripts/fuzz.sh)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libvtk9-dev               # .vtu/.vtp input and output, cell validator
  libtet1.5-dev             # tetrahedral fill
  libgtest-dev              # tests
  libbenchmark-dev          # benchmarks
  libtbb-dev                # threads
  libcli11-dev              # command line
  libtomlplusplus-dev       # case files
  nlohmann-json3-dev        # reports
  libcgal-dev libgmp-dev libmpfr-dev  # exact predicates: orient3d, the hull of face normals, the plane facet
  zlib1g-dev
  liblz4-dev                # .vtu output with --vtk-compressor lz4
  libxml2-utils             # tests: xmllint checks that every .vtu/.vtp is well-formed XML
  python3-meshio            # tests: meshio (run by /usr/bin/python3) as an independent .vtu, .su2 and .msh reader
  libcgns-dev               # CGNS output
  cgns-convert              # tests: cgnscheck judges the CGNS output
  openfoam                  # tests: checkMesh judges the polyMesh output, gmshToFoam reads the MSH output
  gmsh                      # tests: gmsh re-reads the MSH output
)
for option in "$@"; do
  case "$option" in
    --extras) packages+=(python3-vtk9 xvfb xauth bc time valgrind) ;;
    --fuzz) packages+=(clang-14 libclang-rt-14-dev llvm-14) ;;
    *) echo "install-deps.sh: unknown option $option" >&2; exit 1 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
echo "Installing: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
