#include "blayer/io/openfoam_writer.h"

#include <filesystem>
#include <limits>

#include "text_output.h"

namespace blayer {

namespace {

namespace fs = std::filesystem;

const char* openfoam_patch_type(PatchKind k) {
  switch (k) {
    case PatchKind::kWall: return "wall";
    case PatchKind::kSymmetry: return "symmetryPlane";
    case PatchKind::kFarfield:
    case PatchKind::kOpen: return "patch";
  }
  return "patch";
}

bool needs_64bit_labels(const SolverMesh& m) {
  const std::size_t limit = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  return m.cells.points.size() > limit || m.cells.n_cells() > limit || m.faces.size() > limit;
}

void header(TextOutput& out, const SolverMesh* m, const char* cls, const char* location, const char* object,
            const std::string& note = {}) {
  out << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n";
  if (m) out << "    arch        \"LSB;label=" << (needs_64bit_labels(*m) ? "64" : "32") << ";scalar=64\";\n";
  out << "    class       " << cls << ";\n";
  if (!note.empty()) out << "    note        \"" << note << "\";\n";
  out << "    location    \"" << location << "\";\n    object      " << object << ";\n}\n\n";
}

void write_points(const SolverMesh& m, const std::string& path, const std::string& target) {
  TextOutput out(path, target);
  header(out, &m, "vectorField", "constant/polyMesh", "points");
  out << m.cells.points.size() << "\n(\n";
  for (const Vec3& p : m.cells.points) out << '(' << p[0] << ' ' << p[1] << ' ' << p[2] << ")\n";
  out << ")\n";
  out.close();
}

void write_faces(const SolverMesh& m, const std::string& path, const std::string& target) {
  TextOutput out(path, target);
  header(out, &m, "faceList", "constant/polyMesh", "faces");
  out << m.faces.size() << "\n(\n";
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const int n = m.faces.n_nodes[f];
    out << n << '(';
    for (int k = 0; k < n; ++k) out << (k ? " " : "") << m.faces.nodes[f][k];
    out << ")\n";
  }
  out << ")\n";
  out.close();
}

void write_labels(const SolverMesh& m, const std::vector<std::int64_t>& labels, std::size_t n, const char* object,
                  const std::string& path, const std::string& target) {
  TextOutput out(path, target);
  const std::string note = "nPoints:" + std::to_string(m.cells.points.size()) +
                           "  nCells:" + std::to_string(m.cells.n_cells()) +
                           "  nFaces:" + std::to_string(m.faces.size()) +
                           "  nInternalFaces:" + std::to_string(m.faces.n_internal);
  header(out, &m, "labelList", "constant/polyMesh", object, note);
  out << n << "\n(\n";
  for (std::size_t i = 0; i < n; ++i) out << labels[i] << '\n';
  out << ")\n";
  out.close();
}

void write_boundary(const SolverMesh& m, const std::string& path, const std::string& target) {
  TextOutput out(path, target);
  header(out, &m, "polyBoundaryMesh", "constant/polyMesh", "boundary");
  out << m.patches.size() << "\n(\n";
  for (const BoundaryPatch& p : m.patches) {
    out << "    " << p.name << "\n    {\n        type            " << openfoam_patch_type(p.kind) << ";\n";
    if (p.kind == PatchKind::kWall) out << "        inGroups        1(wall);\n";
    out << "        nFaces          " << p.size << ";\n        startFace       " << p.start << ";\n    }\n";
  }
  out << ")\n";
  out.close();
}

std::string trimmed(const std::string& output) {
  std::string s = output;
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

}  // namespace

void write_openfoam_polymesh(const SolverMesh& mesh, const std::string& dir, const std::string& target) {
  const fs::path d(dir);
  write_points(mesh, (d / "points").string(), target + "/points");
  write_faces(mesh, (d / "faces").string(), target + "/faces");
  write_labels(mesh, mesh.faces.owner, mesh.faces.size(), "owner", (d / "owner").string(), target + "/owner");
  write_labels(mesh, mesh.faces.neighbour, mesh.faces.n_internal, "neighbour", (d / "neighbour").string(),
               target + "/neighbour");
  write_boundary(mesh, (d / "boundary").string(), target + "/boundary");
}

void write_openfoam_system(const std::string& dir, const std::string& target) {
  const fs::path d(dir);
  auto dictionary = [&](const char* name, const char* body) {
    TextOutput out((d / name).string(), target + "/" + name);
    header(out, nullptr, "dictionary", "system", name);
    out << body;
    out.close();
  };
  dictionary("controlDict",
             "application     simpleFoam;\nstartFrom       startTime;\nstartTime       0;\n"
             "stopAt          endTime;\nendTime         1;\ndeltaT          1;\n"
             "writeControl    timeStep;\nwriteInterval   1;\nwriteFormat     ascii;\n");
  dictionary("fvSchemes",
             "ddtSchemes           { default steadyState; }\ngradSchemes          { default Gauss linear; }\n"
             "divSchemes           { default none; }\nlaplacianSchemes     { default Gauss linear corrected; }\n"
             "interpolationSchemes { default linear; }\nsnGradSchemes        { default corrected; }\n");
  dictionary("fvSolution", "solvers {}\n");
}

bool is_openfoam_polymesh_path(const std::string& output) {
  const fs::path p(trimmed(output));
  return p.filename() == "polyMesh" && p.parent_path().filename() == "constant";
}

std::string openfoam_polymesh_dir(const std::string& output) {
  if (is_openfoam_polymesh_path(output)) return trimmed(output);
  return (fs::path(trimmed(output)) / "constant" / "polyMesh").string();
}

}  // namespace blayer
