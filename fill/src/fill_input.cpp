#include "fill_input.h"

#include <cmath>
#include <sstream>

#include "blayer/core/degenerate_triangle.h"
#include "blayer/core/edge_topology.h"
#include "blayer/core/errors.h"
#include "blayer/core/tolerances.h"

namespace blayer::fill_detail {
namespace {

// Index range, repeated points, finite points and area of every triangle.
void check_triangles(const TriSurface& s, const std::string& what) {
  const int np = static_cast<int>(s.points.size());
  const double rel_height = default_tolerances().degenerate_relative_height;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Triangle& tri = s.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] < 0 || tri[k] >= np)
        throw InputError(what + " triangle " + std::to_string(t) + " refers to point " + std::to_string(tri[k]) +
                         ", outside [0, " + std::to_string(np) + ")");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw InputError(what + " triangle " + std::to_string(t) + " repeats a point");
    for (int k = 0; k < 3; ++k)
      if (!is_finite(s.points[tri[k]])) throw InputError(what + " point " + std::to_string(tri[k]) + " is not finite");
    if (is_degenerate_triangle(s, tri, rel_height))
      throw InputError(what + " triangle " + std::to_string(t) + " is degenerate (zero area) at " +
                       format_point(s.points[tri[0]]) + "; remove slivers before the fill");
  }
}

// "boundary edge (3, 7) at (x, y, z), triangle 12" for the first edge of that kind.
std::string first_edge_of_kind(const TriSurface& s, const EdgeTopology& edges, EdgeKind kind) {
  for (const SurfaceEdge& e : edges.edges) {
    if (e.kind != kind) continue;
    const std::string problem = kind == EdgeKind::kBoundary      ? "boundary edge"
                                : kind == EdgeKind::kNonManifold ? "edge shared by " + std::to_string(e.n_uses) +
                                                                       " triangles"
                                                                 : "edge whose two triangles have opposite orientation";
    return problem + " (" + std::to_string(e.lo) + ", " + std::to_string(e.hi) + ") at " +
           format_point(s.points[e.lo]) + ", triangle " + std::to_string(e.triangle[0]);
  }
  return "";
}

}  // namespace

std::string format_point(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return s.str();
}

void check_fill_options(const FillOptions& opt) {
  const bool outside = opt.region == FillOptions::Region::kOutside;
  if (!(opt.growth >= 1.0) || !std::isfinite(opt.growth))
    throw InputError("fill: growth must be >= 1, got " + std::to_string(opt.growth));
  if (!(opt.quality_radius_edge > 1.0) || !std::isfinite(opt.quality_radius_edge))
    throw InputError("fill: quality_radius_edge must be > 1 (TetGen does not terminate below), got " +
                     std::to_string(opt.quality_radius_edge));
  if (!(opt.envelope_size >= 0.0) || !std::isfinite(opt.envelope_size))
    throw InputError("fill: envelope_size must be >= 0, got " + std::to_string(opt.envelope_size));
  if (opt.max_steiner_points < 0) throw InputError("fill: max_steiner_points must be >= 0");
  if (outside && !opt.farfield && !(opt.farfield_scale > 1.0 && std::isfinite(opt.farfield_scale)))
    throw InputError("fill: farfield_scale must be > 1, got " + std::to_string(opt.farfield_scale));
  if (!outside && opt.farfield)
    throw InputError("fill: a farfield surface is only used with region outside (external flow)");
  if (opt.symmetry && (!outside || opt.farfield))
    throw InputError("fill: a half model (symmetry plane) is filled for external flow with the generated farfield "
                     "box only (no --farfield surface, no --side inward)");
}

void check_closed_surface(const TriSurface& s, const std::string& what) {
  if (s.triangles.empty()) throw InputError(what + " has no triangles");
  check_triangles(s, what);
  const EdgeTopology edges = build_edge_topology(s);
  if (edges.n_boundary > 0)
    throw InputError(what + " is open: " + std::to_string(edges.n_boundary) + " boundary edges, first: " +
                     first_edge_of_kind(s, edges, EdgeKind::kBoundary) + "; the tet fill needs a closed surface");
  if (edges.n_non_manifold > 0)
    throw InputError(what + " is not edge-manifold: " + std::to_string(edges.n_non_manifold) +
                     " edges with more than two triangles, first: " +
                     first_edge_of_kind(s, edges, EdgeKind::kNonManifold));
  if (edges.n_inconsistent > 0)
    throw InputError(what + " is not consistently oriented: " + std::to_string(edges.n_inconsistent) +
                     " edges, first: " + first_edge_of_kind(s, edges, EdgeKind::kInconsistent));
}

EnvelopeParts classify_envelope_parts(const TriSurface& envelope, FillOptions::Region region) {
  const bool outside = region == FillOptions::Region::kOutside;
  EnvelopeParts parts;
  parts.components = edge_connected_components(envelope, build_edge_topology(envelope));
  parts.volume = component_signed_volumes(envelope, parts.components);
  int n_walls = 0;
  for (int c = 0; c < parts.components.count; ++c) {
    const double v = parts.volume[c];
    if (v < 0.0) {
      ++n_walls;
      if (outside)
        throw InputError("envelope component " + std::to_string(c) + " encloses negative volume (" +
                         std::to_string(v) +
                         "): its normals point into its body. For internal flow use region inside "
                         "(--side inward); otherwise the envelope is inverted");
    } else if (v == 0.0) {
      throw InputError("envelope component " + std::to_string(c) + " encloses zero volume");
    }
  }
  if (!outside && n_walls == 0)
    throw InputError(
        "fill region inside: no envelope component has normals pointing into an "
        "enclosed volume; the envelope faces outward, use region outside (external flow)");
  return parts;
}

}  // namespace blayer::fill_detail
