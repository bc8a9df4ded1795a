#include <cstdio>
#include <map>

#include "blayer/core/errors.h"
#include "blayer/io/vtk_io.h"
#include "blayer/quality/cell_validity.h"
#include "commands.h"
#include "run_timer.h"

namespace blayer {

int run_check_command(const ParamValues& params) {
  const std::string input = params.get_string("input");
  if (input.empty()) throw InputError("no mesh given (blayer check MESH.vtu)");
  RunTimer timer;
  const VolumeMeshFile file = read_volume_mesh(input);
  const VolumeMesh& m = file.mesh;
  std::map<std::string, long> per_type;
  long inverted = 0, flat = 0;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    Vec3 corners[8];
    const int n = corner_count(m.cell_types[c]);
    for (int k = 0; k < n; ++k) corners[k] = m.points[m.connectivity[m.offsets[c] + k]];
    const Validity v = cell_validity(m.cell_types[c], corners);
    inverted += v == Validity::kInverted;
    flat += v == Validity::kFlat;
    ++per_type[cell_type_name(m.cell_types[c])];
  }
  std::printf("blayer check: %s: %zu points, %zu cells\n", input.c_str(), m.points.size(), m.n_cells());
  for (const auto& [name, count] : per_type) std::printf("  %-8s %ld\n", name.c_str(), count);
  std::printf("  inverted %ld, flat %ld (%.2f s)\n", inverted, flat, timer.seconds());
  return inverted > 0 ? 2 : 0;
}

}  // namespace blayer
