#include "blayer/io/prepare_surface.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "blayer/core/assert.h"
#include "blayer/core/degenerate_triangle.h"
#include "blayer/core/edge_topology.h"
#include "blayer/core/errors.h"
#include "blayer/core/surface_components.h"
#include "blayer/core/vertex_fans.h"

namespace blayer {

namespace {

// Problems of one kind are listed up to this many; the rest are counted. Enough to see
// a pattern, short enough to read on a terminal.
constexpr int kListedPerKind = 5;

class ProblemList {
 public:
  explicit ProblemList(std::string file) : file_(std::move(file)) {}

  void add(const std::string& kind, const std::string& text) {
    auto& k = kinds_[kind];
    if (k.first == 0) order_.push_back(kind);
    if (k.first < kListedPerKind) k.second.push_back(text);
    ++k.first;
  }
  bool empty() const { return order_.empty(); }

  [[noreturn]] void raise() const {
    std::ostringstream os;
    os << file_ << ": the surface cannot be used:";
    for (const std::string& kind : order_) {
      const auto& k = kinds_.at(kind);
      os << "\n  " << kind << " (" << k.first << "):";
      for (const std::string& t : k.second) os << "\n    " << t;
      if (k.first > kListedPerKind) os << "\n    ... and " << (k.first - kListedPerKind) << " more";
    }
    throw InputError(os.str());
  }
  void raise_if_any() const {
    if (!empty()) raise();
  }

 private:
  std::string file_;
  std::vector<std::string> order_;
  std::unordered_map<std::string, std::pair<int, std::vector<std::string>>> kinds_;
};

std::string fmt_point(const Vec3& p) {
  std::ostringstream os;
  os.precision(10);
  os << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return os.str();
}

// How a triangle is named in messages: its index, the file's face it came from when
// polygons were split, and its vertices.
struct TriangleNames {
  const TriSurface& surface;
  const std::vector<int>& source_face;
  bool triangulated = false;

  std::string operator()(int tri) const {
    const Triangle& t = surface.triangles[tri];
    std::ostringstream os;
    os << "triangle " << tri;
    if (triangulated) os << " (from face " << source_face[tri] << ")";
    os << " [vertices " << t[0] << ", " << t[1] << ", " << t[2] << "]";
    return os.str();
  }
};


// Face sizes and vertex indices, before anything is built from them.
void check_faces(const PolygonSoup& soup, ProblemList& problems) {
  const int nv = static_cast<int>(soup.points.size());
  for (int i = 0; i < nv; ++i)
    if (!is_finite(soup.points[i]))
      problems.add("non-finite coordinates", "vertex " + std::to_string(i) + " at " + fmt_point(soup.points[i]));
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const auto& face = soup.faces[f];
    if (face.size() < 3) {
      problems.add("faces with fewer than 3 vertices",
                   "face " + std::to_string(f) + " has " + std::to_string(face.size()) + " vertices");
      continue;
    }
    for (std::size_t k = 0; k < face.size(); ++k) {
      if (face[k] < 0 || face[k] >= nv) {
        problems.add("vertex indices out of range", "face " + std::to_string(f) + " refers to vertex " +
                                                        std::to_string(face[k]) + " but the file has " +
                                                        std::to_string(nv) + " vertices");
        break;
      }
      if (std::count(face.begin(), face.end(), face[k]) > 1) {
        problems.add("degenerate faces", "face " + std::to_string(f) + " uses vertex " + std::to_string(face[k]) +
                                             " more than once");
        break;
      }
    }
  }
}

// Polygons are split as fans from their first vertex; a non-convex polygon may give
// degenerate or folded triangles, which the later checks then report. Returns the
// number of polygons split; source_face[t] is the file's face of triangle t.
int triangulate(const PolygonSoup& soup, TriSurface& s, std::vector<int>& source_face) {
  s.points = soup.points;
  int n_polygons = 0;
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const auto& face = soup.faces[f];
    if (face.size() > 3) ++n_polygons;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      s.triangles.push_back({face[0], face[k], face[k + 1]});
      source_face.push_back(f);
    }
  }
  return n_polygons;
}

void check_triangles(const TriSurface& s, const TriangleNames& name, const Tolerances& tol, ProblemList& problems) {
  const int nt = static_cast<int>(s.triangles.size());
  for (int t = 0; t < nt; ++t)
    if (is_degenerate_triangle(s, s.triangles[t], tol.degenerate_relative_height))
      problems.add("degenerate (zero-area) triangles", name(t));
  // Duplicates: sort the triangles by their sorted vertex triples and compare neighbours.
  std::vector<std::pair<Triangle, int>> keyed(nt);
  for (int t = 0; t < nt; ++t) {
    keyed[t] = {s.triangles[t], t};
    std::sort(keyed[t].first.begin(), keyed[t].first.end());
  }
  std::sort(keyed.begin(), keyed.end());
  for (int i = 1; i < nt; ++i)
    if (keyed[i].first == keyed[i - 1].first)
      problems.add("duplicate triangles", name(keyed[i].second) + " repeats " + name(keyed[i - 1].second));
}

// Edges in (lo, hi) order, so the problems are listed in the same order every run.
void check_edges(const EdgeTopology& edges, const TriangleNames& name, bool allow_open, ProblemList& problems) {
  for (const SurfaceEdge& e : edges.edges) {
    const std::string edge = "edge (" + std::to_string(e.lo) + ", " + std::to_string(e.hi) + ")";
    if (e.kind == EdgeKind::kNonManifold)
      problems.add("non-manifold edges", edge + " is shared by " + std::to_string(e.n_uses) + " triangles");
    else if (e.kind == EdgeKind::kBoundary && !allow_open)
      problems.add("open boundary edges (holes)", edge + " of " + name(e.triangle[0]) + " has no neighbour");
    else if (e.kind == EdgeKind::kInconsistent)
      problems.add("inconsistent orientation",
                   name(e.triangle[0]) + " and " + name(e.triangle[1]) + " run the same way along " + edge);
  }
}

void check_vertices(const TriSurface& s, ProblemList& problems) {
  std::vector<char> used(s.points.size(), 0);
  for (const Triangle& t : s.triangles)
    for (int v : t) used[v] = 1;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) problems.add("unused vertices", "vertex " + std::to_string(v) + " is used by no triangle");
  const VertexFans fans = build_vertex_fans(s);
  for (int v : fans.non_manifold)
    problems.add("non-manifold vertices",
                 "vertex " + std::to_string(v) + " at " + fmt_point(s.points[v]) +
                     ": its triangles form more than one fan (surfaces touching at a point)");
}

// Flips each component as needed so that its normals point into the fluid, and says so
// in out.notes. Precondition: the surface passed every other check (edge-manifold,
// consistently oriented).
void orient_components(const EdgeTopology& edges, const PrepareOptions& opt, const Tolerances& tol,
                       ProblemList& problems, PreparedSurface& out) {
  const bool half_model = out.symmetry.has_value();
  TriSurface& s = out.surface;
  BLAYER_ASSERT(edges.n_non_manifold == 0 && edges.n_inconsistent == 0);
  const SurfaceComponents comps = edge_connected_components(s, edges);
  out.n_components = comps.count;
  const std::vector<int>& comp = comps.of_triangle;
  std::vector<char> comp_open(out.n_components, 0);
  for (const SurfaceEdge& e : edges.edges)
    if (e.kind == EdgeKind::kBoundary) comp_open[comp[e.triangle[0]]] = 1;
  // A half model's components are closed by the symmetry plane: about a point of the
  // plane the cut's faces would add nothing to the signed volume.
  std::vector<double> volume;
  if (half_model) {
    TriSurface about_plane = s;
    const Vec3 o = out.symmetry->project(Vec3{0.0, 0.0, 0.0});
    for (Vec3& p : about_plane.points) p = p - o;
    volume = component_signed_volumes(about_plane, comps);
  } else {
    volume = component_signed_volumes(s, comps);
  }
  const double diag = bounding_box_diagonal(s.points);
  std::vector<char> flip(out.n_components, 0);
  for (int c = 0; c < out.n_components; ++c) {
    if (comp_open[c] && !half_model) {
      flip[c] = opt.side == Side::kInward;
      continue;
    }
    // A closed component whose volume is this small relative to the model is flat
    // (e.g. a doubled sheet): it has no inside to decide a side from.
    if (std::abs(volume[c]) <= tol.degenerate_relative_height * diag * diag * diag)
      problems.add("closed components enclosing no volume", "component " + std::to_string(c) +
                                                                " (signed volume " + std::to_string(volume[c]) + ")");
    out.enclosed_volume += std::abs(volume[c]);
    const bool points_outward = volume[c] > 0;
    flip[c] = (opt.side == Side::kOutward) != points_outward;
  }
  problems.raise_if_any();
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    if (flip[comp[t]]) std::swap(s.triangles[t][1], s.triangles[t][2]);
  for (int c = 0; c < out.n_components; ++c) {
    if (!flip[c]) continue;
    ++out.n_flipped_components;
    if (comp_open[c] && !half_model)
      out.notes.push_back("open component " + std::to_string(c) + ": winding reversed for --side inward");
    else
      out.notes.push_back(std::string("closed component ") + std::to_string(c) + " was oriented " +
                          (volume[c] > 0 ? "outward" : "inward") + "; flipped so that layers grow " +
                          (opt.side == Side::kOutward ? "outward (external flow)" : "inward (internal flow)"));
  }
}

}  // namespace

PreparedSurface prepare_surface(const PolygonSoup& soup, const std::string& file, const PrepareOptions& opt,
                                const Tolerances& tol) {
  ProblemList problems(file);
  if (soup.faces.empty()) throw InputError(file + ": the file contains no faces");
  check_faces(soup, problems);
  problems.raise_if_any();

  PreparedSurface out;
  std::vector<int> source_face;
  const int n_polygons = triangulate(soup, out.surface, source_face);
  const TriSurface& s = out.surface;
  const TriangleNames name{s, source_face, n_polygons > 0};
  if (n_polygons > 0)
    out.notes.push_back("triangulated " + std::to_string(n_polygons) + " polygons into triangles (" +
                        std::to_string(s.triangles.size()) + " triangles in all); triangle numbers below refer to "
                        "the triangulated surface");

  check_triangles(s, name, tol, problems);
  const EdgeTopology edges = build_edge_topology(s);
  check_edges(edges, name, /*allow_open=*/true, problems);
  problems.raise_if_any();
  SymmetryFinding symmetry = find_symmetry_plane(s, edges, opt.symmetry);
  // A found plane that does not make a clean half model (faces in it, the surface on
  // both sides) is only an error when the user did not allow open surfaces: a flat
  // open plate's boundary lies in its own plane too.
  if (!symmetry.problems.empty() && opt.symmetry.mode == SymmetryMode::kAuto && opt.allow_open) symmetry = {};
  for (const std::string& p : symmetry.problems) problems.add("symmetry plane", p);
  problems.raise_if_any();
  check_edges(edges, name, opt.allow_open || symmetry.plane.has_value(), problems);
  problems.raise_if_any();
  check_vertices(s, problems);
  problems.raise_if_any();

  if (symmetry.plane) {
    snap_to_symmetry_plane(symmetry, &out.surface);
    out.symmetry = symmetry.plane;
    out.n_symmetry_points = static_cast<int>(symmetry.plane_points.size());
    out.symmetry_snap = symmetry.max_snap;
    std::ostringstream note;
    note << "half model: the open boundary (" << out.n_symmetry_points << " points) lies in the symmetry plane "
         << symmetry.plane->describe() << (opt.symmetry.mode == SymmetryMode::kAuto ? " (found)" : "")
         << "; its points were snapped onto it (by at most " << symmetry.max_snap << ")";
    out.notes.push_back(note.str());
  }
  orient_components(edges, opt, tol, problems, out);
  out.closed = edges.n_boundary == 0;
  if (!out.closed && !out.symmetry)
    out.notes.push_back("open surface (" + std::to_string(edges.n_boundary) +
                        " boundary edges): layers grow on the side the triangles' normals point to");
  return out;
}

PreparedSurface load_surface(const std::string& path, const PrepareOptions& opt, const Tolerances& tol) {
  return prepare_surface(read_polygon_soup(path), path, opt, tol);
}

}  // namespace blayer
