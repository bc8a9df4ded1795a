#include "farfield.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"
#include "blayer/core/point_in_surface.h"
#include "fill_input.h"

namespace blayer::fill_detail {
namespace {

// Samples per box face side when looking for the smallest target size on the box.
constexpr int kBoxSamples = 9;

// skip_axis / skip_side: a face left out (a half box's face on the symmetry plane,
// which touches the body); -1: none.
double smallest_size_on_box(const Vec3& lo, const Vec3& hi, const SizeField& size, int skip_axis = -1,
                            int skip_side = 0) {
  double smallest = std::numeric_limits<double>::max();
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < kBoxSamples && !(axis == skip_axis && side == skip_side); ++i)
        for (int j = 0; j < kBoxSamples; ++j) {
          Vec3 x;
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          x[axis] = side ? hi[axis] : lo[axis];
          x[u] = lo[u] + (hi[u] - lo[u]) * i / (kBoxSamples - 1);
          x[v] = lo[v] + (hi[v] - lo[v]) * j / (kBoxSamples - 1);
          smallest = std::min(smallest, size(x));
        }
  return smallest;
}

// Lattice points on the surface of the box with n[k] cells along axis k, in lattice
// order; id maps a lattice index to its point (-1 inside the box).
struct BoxLattice {
  int n[3];
  std::vector<int> id;
  long key(int i, int j, int k) const { return (static_cast<long>(i) * (n[1] + 1) + j) * (n[2] + 1) + k; }
};

// skip_axis / skip_side: a face whose interior points are left out (it is not part of
// the surface); -1: none.
BoxLattice box_points(const Vec3& lo, const Vec3& hi, const int n[3], std::vector<Vec3>& points, int skip_axis = -1,
                      int skip_side = 0) {
  BoxLattice l{{n[0], n[1], n[2]}, {}};
  l.id.assign(static_cast<std::size_t>(n[0] + 1) * (n[1] + 1) * (n[2] + 1), -1);
  // End points are set exactly so that the faces meet in identical points.
  auto coord = [&](int a, int idx) { return idx == n[a] ? hi[a] : lo[a] + (hi[a] - lo[a]) * idx / n[a]; };
  for (int i = 0; i <= n[0]; ++i)
    for (int j = 0; j <= n[1]; ++j)
      for (int k = 0; k <= n[2]; ++k) {
        if (i != 0 && i != n[0] && j != 0 && j != n[1] && k != 0 && k != n[2]) continue;
        if (skip_axis >= 0) {
          const int idx[3] = {i, j, k};
          const int u = (skip_axis + 1) % 3, w = (skip_axis + 2) % 3;
          const bool on_face = idx[skip_axis] == (skip_side ? n[skip_axis] : 0);
          const bool face_interior = idx[u] != 0 && idx[u] != n[u] && idx[w] != 0 && idx[w] != n[w];
          if (on_face && face_interior) continue;
        }
        l.id[l.key(i, j, k)] = static_cast<int>(points.size());
        points.push_back({coord(0, i), coord(1, j), coord(2, k)});
      }
  return l;
}

// Two triangles per lattice square of the face (axis, side), wound into the box.
void box_face_triangles(const BoxLattice& l, int axis, int side, TriSurface& box) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Vec3 inward{0, 0, 0};
  inward[axis] = side ? -1.0 : 1.0;
  for (int a = 0; a < l.n[u]; ++a)
    for (int b = 0; b < l.n[v]; ++b) {
      int c[4];
      for (int q = 0; q < 4; ++q) {
        int idx[3];
        idx[axis] = side ? l.n[axis] : 0;
        idx[u] = a + (q == 1 || q == 2);
        idx[v] = b + (q >= 2);
        c[q] = l.id[l.key(idx[0], idx[1], idx[2])];
      }
      // Alternate diagonals so that the faces carry no preferred direction.
      Triangle t1{c[0], c[1], c[2]}, t2{c[0], c[2], c[3]};
      if ((a + b) % 2 == 1) {
        t1 = {c[0], c[1], c[3]};
        t2 = {c[1], c[2], c[3]};
      }
      for (Triangle t : {t1, t2}) {
        if (dot(triangle_area_vector(box, t), inward) < 0) std::swap(t[1], t[2]);
        box.triangles.push_back(t);
      }
    }
}

}  // namespace

HalfBox half_farfield_box(const Vec3& lo_env, const Vec3& hi_env, const SymmetryPlane& plane, double scale,
                          const SizeField& size, double* spacing) {
  BLAYER_ASSERT(plane.axis >= 0);
  const int a = plane.axis;
  const bool model_above = plane.normal[a] > 0.0;
  // The mirrored model's bounding box: symmetric about the plane along a.
  Vec3 lo = lo_env, hi = hi_env;
  const double reach = std::max(std::fabs(hi_env[a] - plane.offset), std::fabs(lo_env[a] - plane.offset));
  lo[a] = plane.offset - reach;
  hi[a] = plane.offset + reach;
  const Vec3 extent = hi - lo;
  const double emax = std::max({extent[0], extent[1], extent[2]});
  Vec3 centre = 0.5 * (lo + hi), half;
  for (int k = 0; k < 3; ++k) half[k] = 0.5 * scale * std::max(extent[k], 0.5 * emax);
  HalfBox box;
  box.lo = centre - half;
  box.hi = centre + half;
  (model_above ? box.lo : box.hi)[a] = plane.offset;  // exactly on the plane
  const int plane_side = model_above ? 0 : 1;
  *spacing = smallest_size_on_box(box.lo, box.hi, size, a, plane_side);
  int n[3];
  for (int k = 0; k < 3; ++k) n[k] = std::max(1, static_cast<int>(std::ceil((box.hi[k] - box.lo[k]) / *spacing)));
  const BoxLattice lattice = box_points(box.lo, box.hi, n, box.surface.points, a, plane_side);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      if (!(axis == a && side == plane_side)) box_face_triangles(lattice, axis, side, box.surface);
  // The plane face's boundary: its four lattice edges.
  const int u = (a + 1) % 3, w = (a + 2) % 3;
  auto id = [&](int iu, int iw) {
    int idx[3];
    idx[a] = plane_side ? n[a] : 0;
    idx[u] = iu;
    idx[w] = iw;
    return lattice.id[lattice.key(idx[0], idx[1], idx[2])];
  };
  for (int iu = 0; iu < n[u]; ++iu)
    for (int iw : {0, n[w]}) box.plane_boundary_edges.push_back({id(iu, iw), id(iu + 1, iw)});
  for (int iw = 0; iw < n[w]; ++iw)
    for (int iu : {0, n[u]}) box.plane_boundary_edges.push_back({id(iu, iw), id(iu, iw + 1)});
  for (const auto& e : box.plane_boundary_edges) {
    box.plane_boundary.push_back(e.first);
    box.plane_boundary.push_back(e.second);
  }
  std::sort(box.plane_boundary.begin(), box.plane_boundary.end());
  box.plane_boundary.erase(std::unique(box.plane_boundary.begin(), box.plane_boundary.end()), box.plane_boundary.end());
  return box;
}

TriSurface farfield_box(const Vec3& lo_env, const Vec3& hi_env, double scale, const SizeField& size, double* spacing) {
  const Vec3 extent = hi_env - lo_env;
  const double emax = std::max({extent[0], extent[1], extent[2]});
  Vec3 centre = 0.5 * (lo_env + hi_env), half;
  for (int k = 0; k < 3; ++k) half[k] = 0.5 * scale * std::max(extent[k], 0.5 * emax);
  const Vec3 lo = centre - half, hi = centre + half;
  *spacing = smallest_size_on_box(lo, hi, size);
  int n[3];
  for (int k = 0; k < 3; ++k) n[k] = std::max(1, static_cast<int>(std::ceil(2.0 * half[k] / *spacing)));
  TriSurface box;
  const BoxLattice lattice = box_points(lo, hi, n, box.points);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) box_face_triangles(lattice, axis, side, box);
  return box;
}

TriSurface user_farfield(const TriSurface& farfield, const TriSurface& envelope,
                         const SurfaceComponents& envelope_components, const SizeField& size,
                         double* size_on_farfield) {
  check_closed_surface(farfield, "farfield");
  TriSurface far = farfield;
  if (signed_volume(far) > 0.0)
    for (Triangle& t : far.triangles) std::swap(t[1], t[2]);
  const double far_diagonal = bounding_box_diagonal(far.points);
  for (int c = 0; c < envelope_components.count; ++c) {
    const auto& of = envelope_components.of_triangle;
    const std::size_t t = static_cast<std::size_t>(std::find(of.begin(), of.end(), c) - of.begin());
    const Vec3& p = envelope.points[envelope.triangles[t][0]];
    if (point_in_closed_surface(far, p, far_diagonal) != Containment::kInside)
      throw InputError("farfield does not enclose envelope component " + std::to_string(c) + " (its point " +
                       format_point(p) + " is outside or on the farfield)");
  }
  *size_on_farfield = 0.0;
  for (const Vec3& p : far.points) *size_on_farfield = std::max(*size_on_farfield, size(p));
  return far;
}

}  // namespace blayer::fill_detail
