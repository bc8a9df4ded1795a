#include "blayer/io/msh_writer.h"

#include <algorithm>
#include <array>
#include <limits>

#include "text_output.h"

namespace blayer {

namespace {

struct GmshType {
  CellType cell;
  int gmsh_id;
  std::array<int, 8> from_vtk;  // gmsh node k is VTK corner from_vtk[k]
};

const std::array<GmshType, 4> kVolumeTypes = {{
    {CellType::kTet, 4, {0, 1, 2, 3}},
    {CellType::kPyramid, 7, {0, 1, 2, 3, 4}},
    {CellType::kWedge, 6, {0, 2, 1, 3, 5, 4}},
    {CellType::kHex, 5, {0, 1, 2, 3, 4, 5, 6, 7}},
}};
constexpr int kTriangle = 2, kQuad = 3;

struct Box {
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max()};
  void add(const Vec3& p) {
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
  }
};

void write_box(TextOutput& out, const Box& b) {
  out << b.lo[0] << ' ' << b.lo[1] << ' ' << b.lo[2] << ' ' << b.hi[0] << ' ' << b.hi[1] << ' ' << b.hi[2];
}

void write_entities(TextOutput& out, const SolverMesh& m) {
  Box all;
  for (const Vec3& p : m.cells.points) all.add(p);
  out << "$Entities\n0 0 " << m.patches.size() << " 1\n";
  for (std::size_t s = 0; s < m.patches.size(); ++s) {
    Box b;
    const BoundaryPatch& p = m.patches[s];
    for (std::size_t f = p.start; f < p.start + p.size; ++f)
      for (int k = 0; k < m.faces.n_nodes[f]; ++k) b.add(m.cells.points[m.faces.nodes[f][k]]);
    out << s + 1 << ' ';
    write_box(out, b);
    out << " 1 " << s + 1 << " 0\n";
  }
  out << "1 ";
  write_box(out, all);
  out << " 1 " << m.patches.size() + 1 << ' ' << m.patches.size();
  for (std::size_t s = 0; s < m.patches.size(); ++s) out << ' ' << s + 1;
  out << "\n$EndEntities\n";
}

void write_nodes(TextOutput& out, const SolverMesh& m) {
  const std::size_t n = m.cells.points.size();
  out << "$Nodes\n1 " << n << " 1 " << n << "\n3 1 0 " << n << '\n';
  for (std::size_t p = 1; p <= n; ++p) out << p << '\n';
  for (const Vec3& p : m.cells.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  out << "$EndNodes\n";
}

void write_elements(TextOutput& out, const SolverMesh& m) {
  // Blocks: one per volume cell type present, one per face type present in each patch.
  std::size_t n_blocks = 0;
  for (const GmshType& t : kVolumeTypes) n_blocks += m.n_cells_of(t.cell) > 0;
  std::vector<std::array<std::size_t, 2>> patch_counts;  // triangles, quads
  for (const BoundaryPatch& p : m.patches) {
    std::array<std::size_t, 2> c{0, 0};
    for (std::size_t f = p.start; f < p.start + p.size; ++f) ++c[m.faces.n_nodes[f] == 3 ? 0 : 1];
    n_blocks += (c[0] > 0) + (c[1] > 0);
    patch_counts.push_back(c);
  }
  const std::size_t n_elements = m.cells.n_cells() + m.n_boundary_faces();
  out << "$Elements\n" << n_blocks << ' ' << n_elements << " 1 " << n_elements << '\n';
  std::size_t tag = 1;
  for (const GmshType& t : kVolumeTypes) {
    const std::size_t count = m.n_cells_of(t.cell);
    if (count == 0) continue;
    out << "3 1 " << t.gmsh_id << ' ' << count << '\n';
    const int n = corner_count(t.cell);
    for (std::size_t c = 0; c < m.cells.n_cells(); ++c) {
      if (m.cells.cell_types[c] != t.cell) continue;
      const PointId* nodes = m.cells.cell_nodes(c);
      out << tag++;
      for (int k = 0; k < n; ++k) out << ' ' << nodes[t.from_vtk[k]] + 1;
      out << '\n';
    }
  }
  for (std::size_t s = 0; s < m.patches.size(); ++s) {
    const BoundaryPatch& p = m.patches[s];
    for (int n_nodes : {3, 4}) {
      const std::size_t count = patch_counts[s][n_nodes == 3 ? 0 : 1];
      if (count == 0) continue;
      out << "2 " << s + 1 << ' ' << (n_nodes == 3 ? kTriangle : kQuad) << ' ' << count << '\n';
      for (std::size_t f = p.start; f < p.start + p.size; ++f) {
        if (m.faces.n_nodes[f] != n_nodes) continue;
        out << tag++;
        for (int k = 0; k < n_nodes; ++k) out << ' ' << m.faces.nodes[f][k] + 1;
        out << '\n';
      }
    }
  }
  out << "$EndElements\n";
}

}  // namespace

void write_msh(const SolverMesh& mesh, const std::string& path, const std::string& target) {
  TextOutput out(path, target);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n" << mesh.patches.size() + 1 << '\n';
  for (std::size_t s = 0; s < mesh.patches.size(); ++s) out << "2 " << s + 1 << " \"" << mesh.patches[s].name << "\"\n";
  out << "3 " << mesh.patches.size() + 1 << " \"fluid\"\n$EndPhysicalNames\n";
  write_entities(out, mesh);
  write_nodes(out, mesh);
  write_elements(out, mesh);
  out.close();
}

}  // namespace blayer
