#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "blayer/core/errors.h"
#include "blayer/core/free_heap.h"
#include "blayer/core/stopwatch.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/extruder/wall_renumbering.h"
#include "blayer/fill/fill_envelope.h"
#include "blayer/fill/hybrid_mesh.h"
#include "blayer/fill/tet_fill.h"
#include "blayer/io/atomic_file.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/vtk_io.h"
#include "blayer/quality/mesh_check.h"
#include "commands.h"
#include "growth_options.h"
#include "huge_pages.h"
#include "mesh_output.h"
#include "surface_options.h"

namespace blayer {

namespace {

ExtrusionParams extrusion_params(const ParamValues& p, const TriSurface& wall, std::vector<std::string>* notes) {
  ExtrusionParams e;
  const GrowthLaw g = growth_law_options(p);
  // The default height is for a user who gave none of the three options; an explicit
  // 0 is the growth law's "derive it" and is left to the law's own checks.
  e.growth = g;
  if (!any_height_given(p)) {
    if (g.relative) throw InputError("--relative-heights needs first-height, total-thickness or last-height");
    std::string note;
    e.growth = with_default_first_height(g, bounding_box_diagonal(wall.points), &note);
    notes->push_back(note);
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
  e.solver_limits = {p.get_real("max-non-orthogonality"), p.get_real("max-skewness"), p.get_real("max-boundary-skewness"),
                     p.get_real("max-face-warp"), p.get_bool("face-pyramids-check"), p.get_bool("face-tets-check")};
  e.direction_repair_passes = p.get_int("direction-repair-passes");
  e.fan_angle_deg = p.get_real("fan-angle");
  e.fan_max_sector_deg = p.get_real("fan-max-sector");
  e.column_directions = p.get_string("column-directions") == "recomputed" ? ColumnDirections::kRecomputed
                                                                         : ColumnDirections::kKept;
  e.limit_policy = p.get_string("limit") == "terminate" ? LimitPolicy::kTerminate : LimitPolicy::kCompress;
  // Every range was checked against the parameter table when the options were read.
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

// The requested outputs (empty: not requested), and where each is staged.
struct ExtrudeOutputs {
  std::string mesh, envelope, boundary, report;
  StagedMesh mesh_staged;
  std::string envelope_tmp, boundary_tmp, report_tmp;
  VtkWriteOptions vtk;
};

// Stages every output before any work, so that a bad output path fails fast.
ExtrudeOutputs stage_outputs(const ParamValues& params, AtomicOutputs& outputs) {
  ExtrudeOutputs o;
  o.mesh = params.get_string("output");
  if (o.mesh.empty()) {
    // "wing.off.gz" -> "wing_layers.vtu" in the current directory.
    const std::string name = std::filesystem::path(params.get_string("input")).filename().string();
    o.mesh = name.substr(0, name.find('.')) + "_layers.vtu";
  }
  o.mesh_staged = stage_mesh_output(o.mesh, params.get_string("format"), outputs);
  o.vtk = vtk_write_options(params);
  o.envelope = params.get_string("envelope");
  o.report = params.get_string("report");
  o.boundary = params.get_string("boundary");
  if (!o.envelope.empty()) o.envelope_tmp = outputs.stage(o.envelope);
  if (!o.report.empty()) o.report_tmp = outputs.stage(o.report);
  if (!o.boundary.empty() && !params.get_bool("fill")) throw InputError("--boundary needs --fill");
  if (!o.boundary.empty()) o.boundary_tmp = outputs.stage(o.boundary);
  return o;
}

// Fills the region beyond the layers with tets and appends them to result.mesh.
struct FilledRegion {
  FillResult fill;
  std::vector<std::int64_t> fill_to_mesh;  // mesh point of every fill point
};

FilledRegion fill_beyond_layers(const ParamValues& params, Side side, const std::optional<SymmetryPlane>& symmetry,
                                ExtrusionResult& result) {
  FillOptions fo;
  fo.symmetry = symmetry;
  fo.region = side == Side::kInward ? FillOptions::Region::kInside : FillOptions::Region::kOutside;
  fo.farfield_scale = params.get_real("farfield-scale");
  fo.growth = params.get_real("fill-growth");
  std::optional<TriSurface> farfield;
  if (!params.get_string("farfield").empty()) {
    PrepareOptions fopt;  // the farfield's own orientation is handled by the fill
    farfield = load_surface(params.get_string("farfield"), fopt).surface;
    fo.farfield = &*farfield;
  }
  std::printf("filling with tetrahedra (TetGen)...\n");
  std::fflush(stdout);
  const FillEnvelope envelope = fill_envelope(result.envelope, result.envelope_point_ids, &result.mesh);
  if (envelope.n_caps > 0)
    std::printf("  %lld pyramids cap the quad tops of fan strips\n", static_cast<long long>(envelope.n_caps));
  FilledRegion f{fill_with_tets(envelope.surface, fo), {}};
  f.fill_to_mesh = append_fill(f.fill, envelope.point_ids, &result.mesh);
  const FillStats& st = f.fill.stats;
  std::printf("  %lld tets, %lld Steiner points, min dihedral %.2f deg, max radius-edge %.3f, %.2f s\n",
              static_cast<long long>(st.n_tets), static_cast<long long>(st.n_steiner_points), st.min_dihedral_deg,
              st.max_radius_edge, st.seconds_total);
  return f;
}

// Volumes of the layer cells (the first n_layer_cells) and of the fill.
struct MeshVolumes {
  double layers = 0.0, fill = 0.0;
};

// The one validity decision of a run: the quality module's exact check of the whole
// assembled mesh (layers and fill). Nothing is written unless it passes; the check's
// per-cell arrays are added to the mesh. *volumes: summed from the check's per-cell
// volumes in double precision, before they are stored as the Float32 array. The
// metrics' percentiles and per-layer summaries only for the JSON report (for_report).
MeshCheckReport decide_validity(VolumeMesh& mesh, std::size_t n_layer_cells, bool for_report, MeshVolumes* volumes) {
  MeshCheckReport check =
      check_volume_mesh(mesh, for_report ? CheckSummaries::kFull : CheckSummaries::kMinMax);
  const std::vector<double>& volume = check.metrics[kVolumeMetric];
  for (std::size_t c = 0; c < volume.size(); ++c) (c < n_layer_cells ? volumes->layers : volumes->fill) += volume[c];
  move_quality_arrays(mesh, &check);
  if (!check.ok())
    throw std::runtime_error("the assembled mesh failed the independent check (" +
                             std::to_string(check.totals.inverted) + " inverted, " +
                             std::to_string(check.totals.twisted) + " twisted, " + std::to_string(check.totals.flat) +
                             " flat, " + std::to_string(check.totals.non_conforming) +
                             " non-conforming); no mesh written");
  return check;
}

nlohmann::json report_json(const ParamValues& params, const ExtrusionReport& r, const MeshCheckReport& check,
                           const MeshVolumes& volumes, const FillStats* fill, double seconds) {
  nlohmann::json j;
  j["volume"] = {{"layers", volumes.layers}, {"fill", volumes.fill}};
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

void write_envelope(const ExtrusionResult& result, const std::string& path, const VtkWriteOptions& vtk) {
  DataArray layers{"layers", 1, ArrayValues(ValueType::kInt32)};
  for (int l : result.column_layers) layers.values.push_back(l);
  DataArray reason{"stop_reason", 1, ArrayValues(ValueType::kInt32)};
  for (StopReason s : result.stop_reason) reason.values.push_back(static_cast<int>(s));
  write_vtp(result.envelope, {layers, reason}, {}, path, vtk);
}

void write_boundary(const MarkedBoundary& b, const std::string& path, const VtkWriteOptions& vtk) {
  DataArray marker{"marker", 1, ArrayValues(std::vector<std::int32_t>(b.marker.begin(), b.marker.end()))};
  write_vtp(b.surface, {}, {marker}, path, vtk);
}

void print_patches(const std::vector<BoundaryPatch>& patches) {
  if (patches.empty()) return;
  std::printf("boundary patches:");
  for (const BoundaryPatch& p : patches) std::printf(" %s (%zu faces)", p.name.c_str(), p.size);
  std::printf("\n");
}

void print_written(const ExtrudeOutputs& o, const MeshCheckReport& check, double check_seconds, double total_seconds) {
  const auto& n = check.totals.by_type;  // tet, pyramid, wedge, hex
  std::printf("check: %zu cells (%zu wedges, %zu pyramids, %zu tets", check.totals.cells, n[2], n[1], n[0]);
  if (n[3] > 0) std::printf(", %zu hexes", n[3]);
  std::printf("), 0 inverted, 0 non-conforming, "
              "min scaled Jacobian %.4f (%.2f s)\n",
              check.min_scaled_jacobian(), check_seconds);
  std::printf("wrote %s", o.mesh.c_str());
  if (!o.envelope.empty()) std::printf(", %s", o.envelope.c_str());
  if (!o.boundary.empty()) std::printf(", %s", o.boundary.c_str());
  if (!o.report.empty()) std::printf(", %s", o.report.c_str());
  std::printf(" (%.2f s in all)\n", total_seconds);
}

// The run's peak resident memory (this process; the fill's isolated TetGen run is a
// child with its own) and whether its large arrays were on huge pages (huge_pages.h).
void print_memory() {
  rusage self{}, children{};
  ::getrusage(RUSAGE_SELF, &self);
  ::getrusage(RUSAGE_CHILDREN, &children);
  std::printf("memory: peak %.1f MB resident", static_cast<double>(self.ru_maxrss) / 1024.0);
  if (children.ru_maxrss > 0)
    std::printf(", largest child process %.1f MB", static_cast<double>(children.ru_maxrss) / 1024.0);
  std::printf("; huge pages %s\n", huge_page_state(current_huge_page_setup(0, nullptr)).c_str());
}

}  // namespace

int run_extrude_command(const ParamValues& params) {
  const Stopwatch total;
  const std::string input = params.get_string("input");
  if (input.empty()) throw InputError("no input surface given (blayer extrude SURFACE -o OUT.vtu)");
  AtomicOutputs outputs;
  const ExtrudeOutputs out = stage_outputs(params, outputs);

  const PrepareOptions surface_opt = surface_options(params);
  PreparedSurface prepared = load_surface(input, surface_opt);
  std::vector<std::string> notes = prepared.notes;
  ExtrusionParams ep = extrusion_params(params, prepared.surface, &notes);
  ep.symmetry = prepared.symmetry;
  std::printf("blayer extrude: %s: %zu points, %zu triangles\n", input.c_str(), prepared.surface.points.size(),
              prepared.surface.triangles.size());
  for (const std::string& n : notes) std::printf("note: %s\n", n.c_str());
  std::fflush(stdout);

  ExtrusionResult result = extrude_layers_in_spatial_order(&prepared.surface, ep, progress_bar());
  release_free_heap();  // the march's working state, freed on its return
  const std::size_t n_layer_cells = result.mesh.n_cells();
  std::printf("%s", format_extrusion_report(result.report).c_str());
  const std::string thin = thickness_warning(result.report);
  if (!thin.empty()) std::printf("warning: %s\n", thin.c_str());
  std::optional<FilledRegion> filled;
  if (params.get_bool("fill")) filled = fill_beyond_layers(params, surface_opt.side, prepared.symmetry, result);

  const Stopwatch check_time;
  MeshVolumes volumes;
  const MeshCheckReport check = decide_validity(result.mesh, n_layer_cells, !out.report.empty(), &volumes);
  const double check_seconds = check_time.seconds();

  std::optional<MarkedBoundary> boundary;
  if (filled)
    boundary = hybrid_boundary(result.mesh, prepared.surface, filled->fill, filled->fill_to_mesh,
                               prepared.symmetry ? &*prepared.symmetry : nullptr);
  PatchSources patch_sources{&prepared.surface, boundary ? &*boundary : nullptr, &result.envelope,
                             &result.envelope_point_ids, prepared.symmetry ? &*prepared.symmetry : nullptr};
  const std::vector<BoundaryPatch> patches = write_mesh_output(out.mesh_staged, result.mesh, patch_sources, out.vtk);
  if (!out.envelope.empty()) write_envelope(result, out.envelope_tmp, out.vtk);
  if (!out.boundary.empty()) write_boundary(*boundary, out.boundary_tmp, out.vtk);
  if (!out.report.empty())
    write_text_file(out.report_tmp,
                    report_json(params, result.report, check, volumes,
                                filled ? &filled->fill.stats : nullptr, total.seconds())
                            .dump(2) +
                        "\n",
                    out.report);
  outputs.commit();
  print_patches(patches);
  print_written(out, check, check_seconds, total.seconds());
  print_memory();
  // A valid, written mesh that is thinner than the user requires: its own exit status.
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
