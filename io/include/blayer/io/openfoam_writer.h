// OpenFOAM's polyMesh: the files points, faces, owner, neighbour and boundary of
// constant/polyMesh, in OpenFOAM's ASCII format (read by every OpenFOAM version and
// by foam-extend, checked with checkMesh).
//
// What OpenFOAM requires, and how it is met:
//   faces          internal faces first, upper-triangular (sorted by owner, then by
//                  neighbour, owner < neighbour), then the boundary faces patch by
//                  patch: SolverMesh's face order as it is.
//   orientation    a face's right-hand normal points from its owner into its neighbour,
//                  and out of the domain on the boundary: SolverMesh's face orientation.
//   patch types    wall -> wall (in group wall), farfield and open -> patch,
//                  symmetry -> symmetryPlane.
//   labels         OpenFOAM's label size is a build option (Debian's 1912 has 32-bit
//                  labels). The ASCII files carry any size; the header's arch entry says
//                  label=64 when a count passes 2^31-1, and such a mesh needs an OpenFOAM
//                  built with WM_LABEL_SIZE=64.
// Points are written with the shortest text that reads back to the same double.
#pragma once

#include <string>

#include "blayer/io/solver_mesh.h"

namespace blayer {

// Writes the five polyMesh files into the existing directory dir (normally a staged
// temporary); target names the directory in error messages. Throws IoError.
void write_openfoam_polymesh(const SolverMesh& mesh, const std::string& dir, const std::string& target);

// Writes system/controlDict, fvSchemes and fvSolution into the existing directory dir:
// the least a case needs for OpenFOAM's utilities (checkMesh, paraFoam, renumberMesh)
// to open it; a solver run replaces them with its own. Throws IoError.
void write_openfoam_system(const std::string& dir, const std::string& target);

// The polyMesh directory of an OpenFOAM output path: "CASE/constant/polyMesh" as given,
// or CASE/constant/polyMesh for a case directory CASE. Trailing slashes are ignored.
std::string openfoam_polymesh_dir(const std::string& output);

// True when output names a polyMesh directory (its last two parts are constant/polyMesh).
bool is_openfoam_polymesh_path(const std::string& output);

}  // namespace blayer
