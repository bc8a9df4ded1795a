#include <cstdio>

#include "blayer/core/errors.h"
#include "blayer/core/stopwatch.h"
#include "blayer/io/atomic_file.h"
#include "blayer/io/vtk_io.h"
#include "mesh_output.h"
#include "blayer/quality/mesh_check.h"
#include "commands.h"

namespace blayer {

int run_check_command(const ParamValues& params) {
  const std::string input = params.get_string("input");
  if (input.empty()) throw InputError("no mesh given (blayer check MESH.vtu)");
  const std::string json = params.get_string("json"), bad = params.get_string("bad");
  AtomicOutputs outputs;
  const std::string json_tmp = json.empty() ? "" : outputs.stage(json);
  const std::string bad_tmp = bad.empty() ? "" : outputs.stage(bad);

  const Stopwatch timer;
  const VolumeMeshFile file = read_volume_mesh(input);
  const double read_seconds = timer.seconds();
  const Stopwatch check_timer;
  const MeshCheckReport report = check_volume_mesh(file.mesh);
  const double check_seconds = check_timer.seconds();

  std::printf("blayer check: %s\n", input.c_str());
  if (file.n_skipped_lower_dimension > 0)
    std::printf("  (%d vertex, line and surface cells in the file were not checked)\n",
                file.n_skipped_lower_dimension);
  std::printf("%s", format_check_report(report).c_str());
  std::printf("  time: read %.2f s, check %.2f s (%.0f cells/s)\n", read_seconds, check_seconds,
              check_seconds > 0 ? static_cast<double>(file.mesh.n_cells()) / check_seconds : 0.0);

  if (!json.empty()) write_text_file(json_tmp, check_report_to_json(report).dump(2) + "\n", json);
  if (!bad.empty()) write_vtu(extract_bad_cells(file.mesh, report), bad_tmp, vtk_write_options(params));
  outputs.commit();
  if (!report.ok()) {
    std::printf("INVALID: %zu inverted, %zu flat, %zu non-conforming cells\n", report.totals.inverted,
                report.totals.flat, report.totals.non_conforming);
    return 2;
  }
  std::printf("valid\n");
  return 0;
}

}  // namespace blayer
