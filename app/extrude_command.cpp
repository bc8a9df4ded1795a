#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "blayer/core/errors.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/fill/tet_fill.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/vtk_io.h"
#include "blayer/quality/mesh_check.h"
#include "commands.h"
#include "output_files.h"
#include "run_timer.h"
#include "surface_options.h"

namespace blayer {

namespace {

// First-layer height when the user gives no height at all: a fraction of the model's
// bounding-box diagonal, small enough for wall-resolved RANS on typical models.
constexpr double kDefaultFirstHeightFraction = 2e-4;

ExtrusionParams extrusion_params(const ParamValues& p, const TriSurface& wall, std::vector<std::string>* notes) {
  ExtrusionParams e;
  GrowthLaw& g = e.growth;
  g.layers = p.get_int("layers");
  g.first_height = p.get_real("first-height");
  g.growth_ratio = p.get_real("growth-ratio");
  g.total_thickness = p.get_real("total-thickness");
  g.last_height = p.get_real("last-height");
  g.relative = p.get_bool("relative-heights");
  if (!p.is_set("first-height") && !p.is_set("total-thickness") && !p.is_set("last-height")) {
    if (g.relative)
      throw InputError("--relative-heights needs first-height, total-thickness or last-height");
    g.first_height = kDefaultFirstHeightFraction * bounding_box_diagonal(wall.points);
    char buf[160];
    std::snprintf(buf, sizeof buf, "no height given: first-height = %.6g (2e-4 x bounding-box diagonal)",
                  g.first_height);
    notes->push_back(buf);
  }
  if (!parse_normal_method(p.get_string("method"), &e.normal_method))
    throw InputError("--method: unknown normal method '" + p.get_string("method") + "'");
  e.normal_smoothing_iterations = p.get_int("normal-smoothing");
  e.height_smoothing_rings = p.get_int("height-smoothing-rings");
  e.proximity_safety = p.get_real("proximity-safety");
  e.max_layer_aspect = p.get_real("max-layer-aspect");
  e.min_visibility = p.get_real("min-visibility");
  e.max_step_stretch = p.get_real("max-step-stretch");
  e.check_collisions = p.get_bool("collision-check");
  e.direction_repair_passes = p.get_int("direction-repair-passes");
  e.column_directions = p.get_string("column-directions") == "recomputed" ? ColumnDirections::kRecomputed
                                                                         : ColumnDirections::kKept;
  e.limit_policy = p.get_string("limit") == "terminate" ? LimitPolicy::kTerminate : LimitPolicy::kCompress;
  if (e.normal_smoothing_iterations < 0 || e.height_smoothing_rings < 0 || e.direction_repair_passes < 0)
    throw InputError("--normal-smoothing, --height-smoothing-rings and --direction-repair-passes must be >= 0");
  if (!(e.proximity_safety > 0.0 && e.proximity_safety <= 1.0))
    throw InputError("--proximity-safety must be in (0, 1]");
  if (!(e.min_visibility > 0.0 && e.min_visibility < 1.0)) throw InputError("--min-visibility must be in (0, 1)");
  if (!(e.max_step_stretch >= 1.0)) throw InputError("--max-step-stretch must be >= 1");
  if (e.max_layer_aspect < 0.0) throw InputError("--max-layer-aspect must be >= 0");
  return e;
}

// A progress bar on a terminal; nothing when stderr is a file or a pipe.
std::function<void(int, int)> progress_bar() {
  if (!::isatty(STDERR_FILENO)) return {};
  return [](int layer, int n) {
    const int width = 30, done = n > 0 ? width * layer / n : width;
    std::fprintf(stderr, "\r  layer %3d/%-3d [%s%s]", layer, n, std::string(done, '#').c_str(),
                 std::string(width - done, ' ').c_str());
    if (layer == n) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  };
}

// Appends the fill's tets to the layer mesh. Envelope point i of the fill is layer-mesh
// point envelope_ids[i]; the fill's other points are appended.
void append_fill(VolumeMesh& mesh, const std::vector<std::int64_t>& envelope_ids, const FillResult& fill,
                 std::size_t n_envelope_points) {
  const std::size_t n_layer_cells = mesh.n_cells();
  const std::int64_t base = static_cast<std::int64_t>(mesh.points.size()) - static_cast<std::int64_t>(n_envelope_points);
  auto map_point = [&](std::int64_t i) {
    return i < static_cast<std::int64_t>(n_envelope_points) ? envelope_ids[i] : base + i;
  };
  for (std::size_t i = n_envelope_points; i < fill.tets.points.size(); ++i) mesh.points.push_back(fill.tets.points[i]);
  for (std::size_t c = 0; c < fill.tets.n_cells(); ++c) {
    std::int64_t nodes[4];
    for (int k = 0; k < 4; ++k) nodes[k] = map_point(fill.tets.connectivity[fill.tets.offsets[c] + k]);
    mesh.add_cell(CellType::kTet, nodes);
  }
  // Point arrays: zero on the new points. Cell arrays: layer -1 on tets; region marks them.
  for (DataArray& a : mesh.point_data) a.values.resize(mesh.points.size() * a.n_components, 0.0);
  for (DataArray& a : mesh.cell_data) a.values.resize(mesh.n_cells() * a.n_components, a.name == "layer" ? -1.0 : 0.0);
  DataArray region{"region", 1, true, std::vector<double>(mesh.n_cells(), 1.0)};
  std::fill(region.values.begin(), region.values.begin() + n_layer_cells, 0.0);
  mesh.cell_data.push_back(std::move(region));
}

nlohmann::json report_json(const ParamValues& params, const ExtrusionReport& r, const MeshCheckReport& check,
                           std::size_t n_layer_cells, const FillStats* fill, double seconds) {
  nlohmann::json j;
  // Volumes of the layer cells and of the fill, from the check's per-cell volumes.
  const auto volume_index = std::find(kCheckMetricNames.begin(), kCheckMetricNames.end(), std::string("volume"));
  const std::vector<double>& volume = check.metrics[volume_index - kCheckMetricNames.begin()];
  double layers_volume = 0.0, fill_volume = 0.0;
  for (std::size_t c = 0; c < volume.size(); ++c) (c < n_layer_cells ? layers_volume : fill_volume) += volume[c];
  j["volume"] = {{"layers", layers_volume}, {"fill", fill_volume}};
  j["config"] = params.effective();
  const nlohmann::json extrusion = extrusion_report_to_json(r);
  for (auto it = extrusion.begin(); it != extrusion.end(); ++it) j[it.key()] = it.value();
  j["check"] = check_report_to_json(check);
  j["time_seconds"]["total"] = seconds;
  if (fill)
    j["fill"] = {{"tets", fill->n_tets},
                 {"steiner_points", fill->n_steiner_points},
                 {"farfield_points", fill->n_farfield_points},
                 {"min_dihedral_deg", fill->min_dihedral_deg},
                 {"max_radius_edge", fill->max_radius_edge},
                 {"seconds", fill->seconds_total}};
  return j;
}

}  // namespace

int run_extrude_command(const ParamValues& params) {
  RunTimer total;
  const std::string input = params.get_string("input");
  if (input.empty()) throw InputError("no input surface given (blayer extrude SURFACE -o OUT.vtu)");
  std::string output = params.get_string("output");
  if (output.empty()) {
    // "wing.off.gz" -> "wing_layers.vtu" in the current directory.
    const std::string name = std::filesystem::path(input).filename().string();
    output = name.substr(0, name.find('.')) + "_layers.vtu";
  }
  if (std::filesystem::path(output).extension() != ".vtu")
    throw InputError(output + ": the output of extrude is a .vtu file");

  // Stage every output before any work, so a bad output path fails fast.
  OutputFiles outputs;
  const std::string vtu_tmp = outputs.stage(output);
  const std::string envelope = params.get_string("envelope"), report = params.get_string("report"),
                    boundary = params.get_string("boundary");
  const std::string envelope_tmp = envelope.empty() ? "" : outputs.stage(envelope);
  const std::string report_tmp = report.empty() ? "" : outputs.stage(report);
  const bool fill = params.get_bool("fill");
  if (!boundary.empty() && !fill) throw InputError("--boundary needs --fill");
  const std::string boundary_tmp = boundary.empty() ? "" : outputs.stage(boundary);

  const PrepareOptions surface_opt = surface_options(params);
  const PreparedSurface prepared = load_surface(input, surface_opt);
  std::vector<std::string> notes = prepared.notes;
  const ExtrusionParams ep = extrusion_params(params, prepared.surface, &notes);
  std::printf("blayer extrude: %s: %zu points, %zu triangles\n", input.c_str(), prepared.surface.points.size(),
              prepared.surface.triangles.size());
  for (const std::string& n : notes) std::printf("note: %s\n", n.c_str());
  std::fflush(stdout);

  ExtrusionResult result = extrude_layers(prepared.surface, ep, progress_bar());
  const std::size_t n_layer_cells = result.mesh.n_cells();
  std::printf("%s", format_extrusion_report(result.report).c_str());
  const std::string thin = thickness_warning(result.report);
  if (!thin.empty()) std::printf("warning: %s\n", thin.c_str());

  std::unique_ptr<FillResult> filled;
  std::unique_ptr<TriSurface> farfield_surface;
  if (fill) {
    FillOptions fo;
    fo.region = surface_opt.side == Side::kInward ? FillOptions::Region::kInside : FillOptions::Region::kOutside;
    fo.farfield_scale = params.get_real("farfield-scale");
    fo.growth = params.get_real("fill-growth");
    if (!params.get_string("farfield").empty()) {
      PrepareOptions fopt;  // the farfield's own orientation is handled by the fill
      farfield_surface = std::make_unique<TriSurface>(load_surface(params.get_string("farfield"), fopt).surface);
      fo.farfield = farfield_surface.get();
    }
    std::printf("filling with tetrahedra (TetGen)...\n");
    std::fflush(stdout);
    filled = std::make_unique<FillResult>(fill_with_tets(result.envelope, fo));
    append_fill(result.mesh, result.envelope_point_ids, *filled, result.envelope.points.size());
    std::printf("  %lld tets, %lld Steiner points, min dihedral %.2f deg, max radius-edge %.3f, %.2f s\n",
                static_cast<long long>(filled->stats.n_tets), static_cast<long long>(filled->stats.n_steiner_points),
                filled->stats.min_dihedral_deg, filled->stats.max_radius_edge, filled->stats.seconds_total);
  }

  RunTimer check_timer;
  const MeshCheckReport check = check_volume_mesh(result.mesh);
  add_quality_arrays(result.mesh, check);
  if (!check.ok())
    throw std::runtime_error("the assembled mesh failed the independent check (" + std::to_string(check.totals.inverted) +
                             " inverted, " + std::to_string(check.totals.flat) + " flat, " +
                             std::to_string(check.totals.non_conforming) + " non-conforming); no mesh written");
  const double check_seconds = check_timer.seconds();

  write_vtu(result.mesh, vtu_tmp);
  if (!envelope.empty()) {
    DataArray layers{"layers", 1, true, {}};
    for (int l : result.column_layers) layers.values.push_back(l);
    DataArray reason{"stop_reason", 1, true, {}};
    for (StopReason s : result.stop_reason) reason.values.push_back(static_cast<int>(s));
    write_vtp(result.envelope, {layers, reason}, {}, envelope_tmp);
  }
  if (!boundary.empty()) {
    // Wall triangles (marker 1) and farfield triangles (marker 2) on the mesh's points.
    TriSurface b;
    b.points = result.mesh.points;
    DataArray marker{"marker", 1, true, {}};
    for (const Triangle& t : prepared.surface.triangles) {
      b.triangles.push_back(t);
      marker.values.push_back(1);
    }
    const std::int64_t base =
        static_cast<std::int64_t>(result.mesh.points.size() - filled->tets.points.size());
    for (std::size_t i = 0; i < filled->boundary.triangles.size(); ++i) {
      if (filled->boundary_marker[i] != kFarfieldMarker) continue;
      Triangle t = filled->boundary.triangles[i];
      for (int& v : t) v = static_cast<int>(base + v);
      // The fill winds farfield triangles into the domain; boundary normals point out.
      std::swap(t[1], t[2]);
      b.triangles.push_back(t);
      marker.values.push_back(2);
    }
    write_vtp(b, {}, {marker}, boundary_tmp);
  }
  if (!report.empty()) {
    std::ofstream(report_tmp) << report_json(params, result.report, check, n_layer_cells, filled ? &filled->stats : nullptr,
                                             total.seconds())
                                     .dump(2)
                              << "\n";
  }
  outputs.commit();

  std::printf("check: %zu cells (%zu wedges, %zu pyramids, %zu tets), 0 inverted, 0 non-conforming, "
              "min scaled Jacobian %.4f (%.2f s)\n",
              check.totals.cells, check.totals.by_type[2], check.totals.by_type[1], check.totals.by_type[0],
              check.min_scaled_jacobian(), check_seconds);
  std::printf("wrote %s", output.c_str());
  if (!envelope.empty()) std::printf(", %s", envelope.c_str());
  if (!boundary.empty()) std::printf(", %s", boundary.c_str());
  if (!report.empty()) std::printf(", %s", report.c_str());
  std::printf(" (%.2f s in all)\n", total.seconds());
  const double required = params.get_real("require-thickness");
  const double reached = 1.0 - result.report.thin.total_columns;
  if (required > 0.0 && reached < required) {
    std::printf("error: %.2f %% of the columns reach 90 %% of the thickness, fewer than --require-thickness %.4g "
                "asks (the mesh is written)\n",
                100.0 * reached, required);
    return kExitThicknessNotReached;
  }
  return 0;
}

}  // namespace blayer
