#include <cstdio>

#include "blayer/core/errors.h"
#include "blayer/core/stopwatch.h"
#include "blayer/extruder/growth_law.h"
#include "blayer/io/atomic_file.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/vtk_io.h"
#include "mesh_output.h"
#include "blayer/quality/mesh_check.h"
#include "blayer/quality/layer_fidelity.h"
#include "commands.h"
#include "growth_options.h"
#include "surface_options.h"

namespace blayer {

namespace {

// With --wall: how faithfully the layers honour the growth law given on the command
// line, measured column by column on the mesh (quality/layer_fidelity.h).
struct FidelityRequest {
  TriSurface wall;
  LayerFidelityTargets targets;
};

FidelityRequest fidelity_request(const ParamValues& params) {
  FidelityRequest r;
  r.wall = load_surface(params.get_string("wall"), surface_options(params)).surface;
  const GrowthLaw g = growth_law_options(params);
  if (!any_height_given(params))
    throw InputError("--wall needs the growth law the layers were asked for (e.g. --first-height H --growth-ratio R)");
  const ResolvedGrowthLaw law = resolve_growth_law(g);
  r.targets = {law.first_height, law.total_thickness, law.layers};
  return r;
}

void print_fidelity(const LayerFidelity& f) {
  auto pct = [](double x) { return 100.0 * x; };
  std::printf("  fidelity: %d columns, %d grown, %d complete (%.2f %% of the wall area covered)\n", f.n_columns,
              f.n_grown, f.n_complete, pct(f.area_coverage));
  std::printf("    first / h1 above the wall planes: p1 %.4f p5 %.4f p50 %.4f p95 %.4f; within 1 %%: %.2f %%\n",
              f.first_over_h1_planes.p1, f.first_over_h1_planes.p5, f.first_over_h1_planes.p50,
              f.first_over_h1_planes.p95, pct(f.first_within_1pct_planes));
  std::printf("    first / h1 as distance to the wall: p1 %.4f p5 %.4f p50 %.4f p95 %.4f; within 1 %%: %.2f %%\n",
              f.first_over_h1_distance.p1, f.first_over_h1_distance.p5, f.first_over_h1_distance.p50,
              f.first_over_h1_distance.p95, pct(f.first_within_1pct_distance));
  std::printf("    top / T above the planes: p5 %.4f p50 %.4f; as distance: p5 %.4f p50 %.4f; >= 0.9 T: %.2f %% / %.2f %%\n",
              f.top_over_T_planes.p5, f.top_over_T_planes.p50, f.top_over_T_distance.p5, f.top_over_T_distance.p50,
              pct(f.top_ge_90pct_planes), pct(f.top_ge_90pct_distance));
}

}  // namespace

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

  nlohmann::json out = check_report_to_json(report);
  if (!params.get_string("wall").empty()) {
    const FidelityRequest fr = fidelity_request(params);
    const LayerFidelity f =
        measure_layer_fidelity(with_wall_points_first(file.mesh, fr.wall), fr.wall, fr.targets);
    print_fidelity(f);
    out["fidelity"] = layer_fidelity_to_json(f);
  }
  if (!json.empty()) write_text_file(json_tmp, out.dump(2) + "\n", json);
  if (!bad.empty()) write_vtu(extract_bad_cells(file.mesh, report), bad_tmp, vtk_write_options(params));
  outputs.commit();
  if (!report.ok()) {
    std::printf("INVALID: %zu inverted, %zu twisted, %zu flat, %zu non-conforming cells\n", report.totals.inverted,
                report.totals.twisted, report.totals.flat, report.totals.non_conforming);
    return 2;
  }
  std::printf("valid\n");
  return 0;
}

}  // namespace blayer
