#include "blayer/io/su2_writer.h"

#include "text_output.h"

namespace blayer {

void write_su2(const SolverMesh& mesh, const std::string& path, const std::string& target) {
  TextOutput out(path, target);
  const VolumeMesh& m = mesh.cells;
  out << "% " << m.n_cells() << " cells and " << mesh.patches.size() << " boundary markers, written by blayer\n";
  out << "NDIME= 3\nNELEM= " << m.n_cells() << '\n';
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    out << static_cast<int>(m.cell_types[c]);
    for (std::int64_t k = m.offsets[c]; k < m.offsets[c + 1]; ++k) out << ' ' << m.connectivity[k];
    out << ' ' << c << '\n';
  }
  out << "NPOIN= " << m.points.size() << '\n';
  for (std::size_t p = 0; p < m.points.size(); ++p)
    out << m.points[p][0] << ' ' << m.points[p][1] << ' ' << m.points[p][2] << ' ' << p << '\n';
  out << "NMARK= " << mesh.patches.size() << '\n';
  for (const BoundaryPatch& patch : mesh.patches) {
    out << "MARKER_TAG= " << patch.name << "\nMARKER_ELEMS= " << patch.size << '\n';
    for (std::size_t f = patch.start; f < patch.start + patch.size; ++f) {
      const int n = mesh.faces.n_nodes[f];
      out << (n == 3 ? 5 : 9);
      for (int k = 0; k < n; ++k) out << ' ' << mesh.faces.nodes[f][k];
      out << '\n';
    }
  }
  out.close();
}

}  // namespace blayer
