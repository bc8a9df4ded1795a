#include "mesh_output.h"

#include <filesystem>

#include "blayer/core/errors.h"
#include "blayer/io/cgns_writer.h"
#include "blayer/io/msh_writer.h"
#include "blayer/io/openfoam_writer.h"
#include "blayer/io/su2_writer.h"

namespace blayer {

namespace {

namespace fs = std::filesystem;

void stage_openfoam(const std::string& output, AtomicOutputs& outputs, StagedMesh* s) {
  const fs::path polymesh(openfoam_polymesh_dir(output));
  const fs::path constant = polymesh.parent_path(), case_dir = constant.parent_path();
  std::error_code ec;
  if (!fs::is_directory(case_dir.empty() ? "." : case_dir, ec)) {
    const std::string tmp = outputs.stage_directory(case_dir.string());
    fs::create_directories(fs::path(tmp) / "constant" / "polyMesh");
    fs::create_directory(fs::path(tmp) / "system");
    s->file_tmp = (fs::path(tmp) / "constant" / "polyMesh").string();
    s->system_tmp = (fs::path(tmp) / "system").string();
    return;
  }
  if (!fs::is_directory(constant, ec)) {
    const std::string tmp = outputs.stage_directory(constant.string());
    fs::create_directory(fs::path(tmp) / "polyMesh");
    s->file_tmp = (fs::path(tmp) / "polyMesh").string();
  } else {
    s->file_tmp = outputs.stage_directory(polymesh.string());
  }
  if (!fs::exists(case_dir / "system", ec)) s->system_tmp = outputs.stage_directory((case_dir / "system").string());
}

PatchTriangles marked_triangles(const MarkedBoundary& b, BoundaryMarker marker, const std::string& name,
                                PatchKind kind) {
  PatchTriangles p{name, kind, {}};
  for (std::size_t t = 0; t < b.surface.triangles.size(); ++t)
    if (b.marker[t] == static_cast<int>(marker)) {
      const Triangle& tri = b.surface.triangles[t];
      p.triangles.push_back({tri[0], tri[1], tri[2]});
    }
  return p;
}

}  // namespace

VtkWriteOptions vtk_write_options(const ParamValues& params) {
  VtkWriteOptions o;
  if (params.get_string("vtk-compressor") == "lz4") o.compressor = VtkCompressor::kLz4;
  return o;
}

StagedMesh stage_mesh_output(const std::string& output, const std::string& format, AtomicOutputs& outputs) {
  StagedMesh s;
  s.target = output;
  s.format = choose_mesh_format(output, format);
  if (s.format == MeshFormat::kOpenFoam)
    stage_openfoam(output, outputs, &s);
  else
    s.file_tmp = outputs.stage(output);
  return s;
}

std::vector<PatchTriangles> standard_patches(const PatchSources& sources) {
  std::vector<PatchTriangles> patches = wall_patches(*sources.wall);
  if (sources.boundary) {
    patches.push_back(marked_triangles(*sources.boundary, BoundaryMarker::kFarfield, "farfield", PatchKind::kFarfield));
    patches.push_back(marked_triangles(*sources.boundary, BoundaryMarker::kSymmetry, "symmetry", PatchKind::kSymmetry));
  } else if (sources.envelope) {
    patches.push_back(patch_triangles("bl_outer", PatchKind::kOpen, *sources.envelope, *sources.envelope_point_ids));
  }
  return patches;
}

std::vector<BoundaryPatch> write_mesh_output(const StagedMesh& staged, const VolumeMesh& mesh,
                                             const PatchSources& sources, const VtkWriteOptions& vtk_options) {
  if (staged.format == MeshFormat::kVtu) {
    write_vtu(mesh, staged.file_tmp, vtk_options);
    return {};
  }
  const SolverMesh solver_mesh = make_solver_mesh(mesh, standard_patches(sources), "bl_side", sources.symmetry);
  switch (staged.format) {
    case MeshFormat::kCgns: write_cgns(solver_mesh, staged.file_tmp, staged.target); break;
    case MeshFormat::kSu2: write_su2(solver_mesh, staged.file_tmp, staged.target); break;
    case MeshFormat::kMsh: write_msh(solver_mesh, staged.file_tmp, staged.target); break;
    case MeshFormat::kOpenFoam:
      write_openfoam_polymesh(solver_mesh, staged.file_tmp, openfoam_polymesh_dir(staged.target));
      if (!staged.system_tmp.empty())
        write_openfoam_system(staged.system_tmp,
                              (fs::path(openfoam_polymesh_dir(staged.target)).parent_path().parent_path() / "system").string());
      break;
    case MeshFormat::kVtu: break;
  }
  return solver_mesh.patches;
}

}  // namespace blayer
