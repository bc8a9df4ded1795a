#include "blayer/io/symmetry_detection.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace blayer {

namespace {

std::vector<int> boundary_points(const EdgeTopology& edges) {
  std::vector<int> p;
  for (const SurfaceEdge& e : edges.edges)
    if (e.kind == EdgeKind::kBoundary) {
      p.push_back(e.lo);
      p.push_back(e.hi);
    }
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  return p;
}

// A coordinate plane holding every given point within tol, if there is one: the
// coordinate is the points' mean, or their common value when they agree exactly.
std::optional<SymmetryPlane> coordinate_plane(const TriSurface& s, const std::vector<int>& pts, double tol) {
  for (int k = 0; k < 3; ++k) {
    double lo = HUGE_VAL, hi = -HUGE_VAL, sum = 0.0;
    for (int v : pts) {
      lo = std::min(lo, s.points[v][k]);
      hi = std::max(hi, s.points[v][k]);
      sum += s.points[v][k];
    }
    if (hi - lo > 2.0 * tol) continue;
    SymmetryPlane p;
    p.axis = k;
    p.normal = {0.0, 0.0, 0.0};
    p.normal[k] = 1.0;
    // 0 when it is within the tolerance of all of them (a cut at y = 0 written with
    // rounding noise is the plane y = 0); else their common value when they agree; else
    // their mean.
    if (std::fabs(lo) <= tol && std::fabs(hi) <= tol)
      p.offset = 0.0;
    else
      p.offset = lo == hi ? lo : sum / static_cast<double>(pts.size());
    return p;
  }
  return std::nullopt;
}

// The plane through the points' centroid normal to their smallest spread, found from
// the boundary edges' Newell normal, if every point lies within tol of it.
std::optional<SymmetryPlane> general_plane(const TriSurface& s, const EdgeTopology& edges,
                                           const std::vector<int>& pts, double tol) {
  Vec3 c{0.0, 0.0, 0.0};
  for (int v : pts) c += s.points[v];
  c = (1.0 / static_cast<double>(pts.size())) * c;
  Vec3 n{0.0, 0.0, 0.0};
  for (const SurfaceEdge& e : edges.edges) {
    if (e.kind != EdgeKind::kBoundary) continue;
    const Vec3 a = s.points[e.lo] - c, b = s.points[e.hi] - c;
    n += e.forward[0] ? cross(a, b) : cross(b, a);
  }
  if (!(norm(n) > 0.0)) return std::nullopt;
  SymmetryPlane p;
  p.normal = normalized(n);
  p.offset = dot(p.normal, c);
  for (int v : pts)
    if (std::fabs(p.signed_distance(s.points[v])) > tol) return std::nullopt;
  return p;
}

std::string fmt(const Vec3& p) {
  std::ostringstream os;
  os.precision(10);
  os << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return os.str();
}

// Turns the normal towards the surface's side; a surface on both sides is a problem.
void orient_to_the_model(const TriSurface& s, double tol, SymmetryPlane* p, std::vector<std::string>* problems) {
  int above = -1, below = -1;
  for (int v = 0; v < static_cast<int>(s.points.size()); ++v) {
    const double d = p->signed_distance(s.points[v]);
    if (d > tol && above < 0) above = v;
    if (d < -tol && below < 0) below = v;
  }
  if (above >= 0 && below >= 0) {
    problems->push_back("the surface lies on both sides of the symmetry plane " + p->describe() + ": point " +
                        std::to_string(above) + " " + fmt(s.points[above]) + " and point " + std::to_string(below) +
                        " " + fmt(s.points[below]));
    return;
  }
  if (below < 0) return;
  p->normal = -1.0 * p->normal;
  // n . x = d becomes (-n) . x = -d; a coordinate plane keeps its coordinate as offset.
  if (p->axis < 0) p->offset = -p->offset;
}

}  // namespace

SymmetryFinding find_symmetry_plane(const TriSurface& s, const EdgeTopology& edges, const SymmetryRequest& request) {
  SymmetryFinding f;
  if (request.mode == SymmetryMode::kNone || edges.n_boundary == 0) return f;
  const double tol = kSymmetryPlaneRelTol * bounding_box_diagonal(s.points);
  const std::vector<int> pts = boundary_points(edges);
  std::optional<SymmetryPlane> plane;
  if (request.mode == SymmetryMode::kPlane) {
    plane = request.plane;
    for (int v : pts)
      if (std::fabs(plane->signed_distance(s.points[v])) > tol) {
        f.problems.push_back("boundary point " + std::to_string(v) + " " + fmt(s.points[v]) + " is " +
                             std::to_string(std::fabs(plane->signed_distance(s.points[v]))) +
                             " from the symmetry plane " + plane->describe() + ": the boundary there is a hole");
        if (f.problems.size() >= 5) break;
      }
  } else {
    plane = coordinate_plane(s, pts, tol);
    if (!plane) plane = general_plane(s, edges, pts, tol);
    if (!plane) return f;  // not a half model: the boundary is a hole
  }
  for (std::size_t t = 0; t < s.triangles.size() && f.problems.size() < 5; ++t) {
    const Triangle& tri = s.triangles[t];
    bool in_plane = true;
    for (int v : tri) in_plane = in_plane && std::fabs(plane->signed_distance(s.points[v])) <= tol;
    if (in_plane)
      f.problems.push_back("triangle " + std::to_string(t) + " [vertices " + std::to_string(tri[0]) + ", " +
                           std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + "] lies in the symmetry plane " +
                           plane->describe() + ": remove the faces on the plane (it is the cut, not a wall)");
  }
  orient_to_the_model(s, tol, &*plane, &f.problems);
  if (!f.problems.empty()) return f;
  f.plane = plane;
  f.plane_points = pts;
  for (int v : pts) f.max_snap = std::max(f.max_snap, std::fabs(plane->signed_distance(s.points[v])));
  return f;
}

void snap_to_symmetry_plane(const SymmetryFinding& f, TriSurface* s) {
  if (!f.plane) return;
  for (int v : f.plane_points) s->points[v] = f.plane->project(s->points[v]);
}

}  // namespace blayer
