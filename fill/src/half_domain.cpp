#include "half_domain.h"

#include <algorithm>

#include "blayer/core/edge_topology.h"
#include "blayer/core/errors.h"
#include "blayer/core/surface_components.h"
#include "farfield.h"
#include "fill_input.h"
#include "plane_facet.h"

namespace blayer::fill_detail {

void check_half_envelope(const TriSurface& envelope, const SymmetryPlane& plane) {
  if (plane.axis < 0)
    throw InputError("fill: a half model's fill needs a coordinate symmetry plane (x, y or z = c), got " +
                     plane.describe());
  if (envelope.triangles.empty()) throw InputError("envelope has no triangles");
  const EdgeTopology edges = build_edge_topology(envelope);
  if (edges.n_non_manifold > 0 || edges.n_inconsistent > 0)
    throw InputError("envelope is not an edge-manifold, consistently oriented surface");
  for (const SurfaceEdge& e : edges.edges) {
    if (e.kind != EdgeKind::kBoundary) continue;
    for (int v : {e.lo, e.hi})
      if (plane.signed_distance(envelope.points[v]) != 0.0)
        throw InputError("envelope boundary edge (" + std::to_string(e.lo) + ", " + std::to_string(e.hi) +
                         ") is open off the symmetry plane " + plane.describe() + ": point " + std::to_string(v) +
                         " " + format_point(envelope.points[v]) + "; the fill needs the envelope closed up to the plane");
  }
}

OuterBoundary half_domain_boundary(const TriSurface& envelope, const SymmetryPlane& plane, const Vec3& lo_env,
                                   const Vec3& hi_env, double scale, const SizeField& size, double* spacing) {
  HalfBox box = half_farfield_box(lo_env, hi_env, plane, scale, size, spacing);
  OuterBoundary outer;
  outer.surface = std::move(box.surface);
  outer.markers.assign(outer.surface.triangles.size(), kFarfieldMarker);
  const int n_box = static_cast<int>(outer.surface.points.size());

  // Plane facet input: the box face's boundary points, then the envelope's cut points.
  PlaneFacetInput in;
  std::vector<int> global;  // facet input point -> outer index (box point, or n_box + envelope point)
  std::vector<int> local_of_box(n_box, -1);
  for (int p : box.plane_boundary) {
    local_of_box[p] = static_cast<int>(in.points.size());
    in.points.push_back(outer.surface.points[p]);
    global.push_back(p);
  }
  for (const auto& e : box.plane_boundary_edges) in.edges.push_back({local_of_box[e.first], local_of_box[e.second]});
  std::vector<int> local_of_env(envelope.points.size(), -1);
  const EdgeTopology edges = build_edge_topology(envelope);
  for (const SurfaceEdge& e : edges.edges) {
    if (e.kind != EdgeKind::kBoundary) continue;
    for (int v : {e.lo, e.hi})
      if (local_of_env[v] < 0) {
        local_of_env[v] = static_cast<int>(in.points.size());
        in.points.push_back(envelope.points[v]);
        global.push_back(n_box + v);
      }
    in.edges.push_back({local_of_env[e.lo], local_of_env[e.hi]});
  }
  // A point of the facet: next to a corner of the box face, far from the layers.
  const int corner = box.plane_boundary_edges.front().first;
  in.inside_point = outer.surface.points[corner] + 0.01 * (0.5 * (box.lo + box.hi) - outer.surface.points[corner]);
  in.inside_point = plane.project(in.inside_point);

  // Target edge length on the facet: kPlaneFacetSizeFactor times the fill's size field,
  // never above the box's spacing (the facet's boundary edges on the box have that
  // length). The facet's new points carry the same size to TetGen.
  const double box_spacing = *spacing;
  auto facet_size = [&](const Vec3& p) { return std::min(kPlaneFacetSizeFactor * size(p), box_spacing); };
  const PlaneFacet facet = triangulate_plane_facet(in, plane, facet_size);
  // The facet's new points join the farfield's; envelope points keep their encoding.
  const int n_in = static_cast<int>(in.points.size());
  std::vector<int> new_index(facet.new_points.size());
  outer.point_size.assign(outer.surface.points.size(), 0.0);
  for (std::size_t j = 0; j < facet.new_points.size(); ++j) {
    new_index[j] = static_cast<int>(outer.surface.points.size());
    outer.surface.points.push_back(facet.new_points[j]);
    outer.point_size.push_back(facet_size(facet.new_points[j]));
  }
  const int n_far = static_cast<int>(outer.surface.points.size());
  auto outer_index = [&](int i) {
    if (i >= n_in) return new_index[i - n_in];
    const int g = global[i];
    return g >= n_box ? n_far + (g - n_box) : g;  // envelope point v encoded as n_far + v
  };
  for (const auto& t : facet.triangles) {
    outer.surface.triangles.push_back({outer_index(t[0]), outer_index(t[1]), outer_index(t[2])});
    outer.markers.push_back(kSymmetryMarker);
  }
  return outer;
}

std::vector<Vec3> closed_body_hole_points(const TriSurface& envelope, double length_scale) {
  const EdgeTopology edges = build_edge_topology(envelope);
  const SurfaceComponents comps = edge_connected_components(envelope, edges);
  std::vector<char> open(comps.count, 0);
  for (const SurfaceEdge& e : edges.edges)
    if (e.kind == EdgeKind::kBoundary) open[comps.of_triangle[e.triangle[0]]] = 1;
  TriSurface bodies;
  bodies.points = envelope.points;
  for (std::size_t t = 0; t < envelope.triangles.size(); ++t)
    if (!open[comps.of_triangle[t]]) bodies.triangles.push_back(envelope.triangles[t]);
  if (bodies.triangles.empty()) return {};
  const EnvelopeParts parts = classify_envelope_parts(bodies, FillOptions::Region::kOutside);
  return hole_points(bodies, parts, true, length_scale);
}

}  // namespace blayer::fill_detail
