// The volume mesh output of `blayer extrude` in any of its formats: staging it before
// the run (so a bad path fails fast and a failed run leaves nothing), and writing it
// with its boundary patches once the mesh is valid.
//
// Patches (solver_mesh.h): one wall patch per wall component ("wall", or "wall_1",
// "wall_2", ...), "farfield" (and "symmetry", when the fill marks any) with --fill,
// "bl_outer" for the outer envelope of a layers-only mesh, and "bl_side" for every
// other boundary face (the side faces over an open surface's boundary edges).
//
// OpenFOAM: the output is CASE/constant/polyMesh or, with --format openfoam, CASE. The
// highest missing directory of CASE, CASE/constant and CASE/constant/polyMesh is staged
// as a whole (a new case appears complete or not at all), and CASE/system gets the
// dictionaries OpenFOAM's utilities need when it does not exist yet.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/fill/hybrid_mesh.h"
#include "blayer/io/atomic_file.h"
#include "blayer/io/mesh_format.h"
#include "blayer/io/solver_mesh.h"
#include "blayer/io/vtk_io.h"
#include "parameters.h"

namespace blayer {

struct StagedMesh {
  std::string target;    // what the user named
  MeshFormat format = MeshFormat::kVtu;
  std::string file_tmp;  // the staged file; for OpenFOAM the staged polyMesh directory
  std::string system_tmp;  // OpenFOAM: staged CASE/system, or empty when it exists
};

// The VTK writer options of a command (--vtk-compressor).
VtkWriteOptions vtk_write_options(const ParamValues& params);

StagedMesh stage_mesh_output(const std::string& output, const std::string& format, AtomicOutputs& outputs);

// Where the boundary patches come from. boundary: the hybrid mesh's marked boundary
// (with --fill), else null; envelope and envelope_point_ids: the layers' outer
// envelope on mesh points.
struct PatchSources {
  const TriSurface* wall = nullptr;
  const MarkedBoundary* boundary = nullptr;
  const TriSurface* envelope = nullptr;
  const std::vector<std::int64_t>* envelope_point_ids = nullptr;
  const SymmetryPlane* symmetry = nullptr;  // a half model's plane: its faces form "symmetry"
};

std::vector<PatchTriangles> standard_patches(const PatchSources& sources);

// Writes the staged mesh; returns the patches written (empty for .vtu), for the user.
std::vector<BoundaryPatch> write_mesh_output(const StagedMesh& staged, const VolumeMesh& mesh,
                                             const PatchSources& sources, const VtkWriteOptions& vtk_options);

}  // namespace blayer
