#include "blayer/fill/tet_fill.h"

#include <algorithm>
#include <sstream>
#include <string>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"
#include "blayer/core/stopwatch.h"
#include "farfield.h"
#include "half_domain.h"
#include "fill_input.h"
#include "size_field.h"
#include "tet_output.h"
#include "tet_plc.h"
#include "tetgen_isolated.h"

namespace blayer {
namespace {

using namespace fill_detail;

// Circumradius of a regular tet of edge 1: TetGen's m switch bounds circumradii, the
// size field speaks of edge lengths.
constexpr double kRegularTetCircumradius = 0.6123724356957945;  // sqrt(6)/4

// Target edge length at each used envelope point: opt.envelope_size, or the mean
// length of the envelope edges at the point; graded away from the envelope by growth.
SizeField envelope_size_field(const TriSurface& envelope, const UsedPoints& used, const FillOptions& opt) {
  std::vector<double> h(envelope.points.size(), 0.0);
  if (opt.envelope_size > 0.0) {
    for (int i : used.used) h[i] = opt.envelope_size;
  } else {
    std::vector<int> count(envelope.points.size(), 0);
    for (const Triangle& t : envelope.triangles)
      for (int k = 0; k < 3; ++k) {
        const double l = norm(envelope.points[t[(k + 1) % 3]] - envelope.points[t[k]]);
        // Each edge appears in two triangles; both ends get it once from each side.
        h[t[k]] += l;
        h[t[(k + 1) % 3]] += l;
        count[t[k]] += 1;
        count[t[(k + 1) % 3]] += 1;
      }
    for (int i : used.used) h[i] /= count[i];
  }
  std::vector<Vec3> sites;
  std::vector<double> sizes;
  for (int i : used.used) {
    sites.push_back(envelope.points[i]);
    sizes.push_back(h[i]);
  }
  return SizeField(std::move(sites), std::move(sizes), opt.growth - 1.0);
}

// TetGen's size at each PLC point (switch m, a circumradius): the outer boundary's own
// size where it gives one (a half model's plane facet points), else the field's.
std::vector<double> point_metrics(const FillPlc& plc, const OuterBoundary& outer, const SizeField& size) {
  BLAYER_ASSERT(outer.point_size.empty() || outer.point_size.size() == outer.surface.points.size());
  const std::size_t n_envelope = plc.envelope.used.size();
  std::vector<double> metric;
  metric.reserve(plc.points.size());
  for (std::size_t j = 0; j < plc.points.size(); ++j) {
    const int outer_point = j < n_envelope ? -1 : plc.farfield.used[j - n_envelope];
    const bool sized_by_outer =
        outer_point >= 0 && !outer.point_size.empty() && outer.point_size[outer_point] > 0.0;
    metric.push_back(kRegularTetCircumradius * (sized_by_outer ? outer.point_size[outer_point] : size(plc.points[j])));
  }
  return metric;
}

void bounding_box(const TriSurface& s, const std::vector<int>& used, Vec3* lo, Vec3* hi) {
  *lo = *hi = s.points[used[0]];
  for (int i : used)
    for (int k = 0; k < 3; ++k) {
      (*lo)[k] = std::min((*lo)[k], s.points[i][k]);
      (*hi)[k] = std::max((*hi)[k], s.points[i][k]);
    }
}

// TetGen's d switch stops after the surface stage and returns only the intersecting
// faces; any face it returns is an error naming the triangles.
void check_self_intersections(const FillPlc& plc, double timeout_seconds) {
  const TetgenMesh d =
      run_tetgen_isolated(plc.tetgen, "pdQ", timeout_seconds,
                          {"tetgen failed during the self-intersection check: ",
                           "; check the envelope for self-intersections and slivers"});
  if (d.faces.empty()) return;
  std::string list;
  const std::size_t n_show = std::min<std::size_t>(3, d.faces.size() / 3);
  for (std::size_t i = 0; i < n_show; ++i)
    list += (i ? "; " : "") + describe_plc_face(plc, {d.faces[3 * i], d.faces[3 * i + 1], d.faces[3 * i + 2]});
  throw InputError("the boundary intersects itself: " + std::to_string(d.faces.size() / 3) +
                   " intersecting triangles, e.g. " + list +
                   "; lower the layer thickness or fix the surface before the fill");
}

std::string meshing_switches(const FillOptions& opt) {
  std::ostringstream sw;
  sw << "pYq" << opt.quality_radius_edge << "mQ";
  if (opt.max_steiner_points > 0) sw << "S" << opt.max_steiner_points;
  return sw.str();
}

}  // namespace

FillResult fill_with_tets(const TriSurface& envelope, const FillOptions& opt) {
  const Stopwatch total;
  const bool outside = opt.region == FillOptions::Region::kOutside;
  const bool half = opt.symmetry.has_value();
  check_fill_options(opt);
  EnvelopeParts parts;
  if (half) {
    check_half_envelope(envelope, *opt.symmetry);
  } else {
    check_closed_surface(envelope, "envelope");
    parts = classify_envelope_parts(envelope, opt.region);
  }

  FillResult result;
  FillStats& st = result.stats;
  UsedPoints env_points = used_points(envelope);
  Vec3 lo, hi;
  bounding_box(envelope, env_points.used, &lo, &hi);
  const SizeField size = envelope_size_field(envelope, env_points, opt);
  st.n_envelope_points = static_cast<std::int64_t>(envelope.points.size());
  st.min_envelope_size = size.min_site_size();
  st.max_envelope_size = size.max_site_size();

  OuterBoundary outer;
  if (half)
    outer = half_domain_boundary(envelope, *opt.symmetry, lo, hi, opt.farfield_scale, size, &st.farfield_size);
  else if (outside && opt.farfield)
    outer.surface = user_farfield(*opt.farfield, envelope, parts.components, size, &st.farfield_size);
  else if (outside)
    outer.surface = farfield_box(lo, hi, opt.farfield_scale, size, &st.farfield_size);
  if (!half) outer.markers.assign(outer.surface.triangles.size(), kFarfieldMarker);
  const TriSurface& far = outer.surface;
  st.n_farfield_points = static_cast<std::int64_t>(far.points.size());

  FillPlc plc = assemble_plc(envelope, std::move(env_points), outer);
  const Stopwatch check_time;
  check_self_intersections(plc, opt.timeout_seconds);
  st.seconds_check = check_time.seconds();

  const std::vector<Vec3> holes =
      half ? closed_body_hole_points(envelope, norm(hi - lo)) : hole_points(envelope, parts, outside, norm(hi - lo));
  for (const Vec3& h : holes) plc.tetgen.holes.insert(plc.tetgen.holes.end(), h.begin(), h.end());
  st.n_holes = static_cast<std::int64_t>(holes.size());
  plc.tetgen.point_metric = point_metrics(plc, outer, size);

  const Stopwatch tetgen_time;
  const TetgenMesh mesh =
      run_tetgen_isolated(plc.tetgen, meshing_switches(opt), opt.timeout_seconds,
                          {"tetgen failed: ", "; check the envelope for slivers and near-touching parts"});
  st.seconds_tetgen = tetgen_time.seconds();

  assemble_fill_result(envelope, outer, plc, mesh, &result);
  check_conformity(result);
  add_quality_stats(&result);
  st.seconds_total = total.seconds();
  return result;
}

}  // namespace blayer
