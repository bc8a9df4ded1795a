#include "blayer/io/prepare_surface.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "blayer/core/errors.h"
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

std::string describe(int tri, int face, const Triangle& t, bool triangulated) {
  std::ostringstream os;
  os << "triangle " << tri;
  if (triangulated) os << " (from face " << face << ")";
  os << " [vertices " << t[0] << ", " << t[1] << ", " << t[2] << "]";
  return os.str();
}

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

PreparedSurface prepare_surface(const PolygonSoup& soup, const std::string& file, const PrepareOptions& opt,
                                const Tolerances& tol) {
  ProblemList problems(file);
  PreparedSurface out;
  const int nv = static_cast<int>(soup.points.size());

  if (soup.faces.empty()) throw InputError(file + ": the file contains no faces");
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
  problems.raise_if_any();

  // Polygons are split as fans from their first vertex; a non-convex polygon may give
  // degenerate or folded triangles, which the checks below then report.
  TriSurface& s = out.surface;
  s.points = soup.points;
  std::vector<int> source_face;
  int n_polygons = 0;
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const auto& face = soup.faces[f];
    if (face.size() > 3) ++n_polygons;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      s.triangles.push_back({face[0], face[k], face[k + 1]});
      source_face.push_back(f);
    }
  }
  const bool triangulated = n_polygons > 0;
  if (triangulated)
    out.notes.push_back("triangulated " + std::to_string(n_polygons) + " polygons into triangles (" +
                        std::to_string(s.triangles.size()) + " triangles in all); triangle numbers below refer to "
                        "the triangulated surface");
  const int nt = static_cast<int>(s.triangles.size());
  auto tri_name = [&](int t) { return describe(t, source_face[t], s.triangles[t], triangulated); };

  for (int t = 0; t < nt; ++t) {
    const Triangle& tr = s.triangles[t];
    double longest2 = 0.0;
    for (int k = 0; k < 3; ++k)
      longest2 = std::max(longest2, norm2(s.points[tr[(k + 1) % 3]] - s.points[tr[k]]));
    const double twice_area = norm(triangle_area_vector(s, tr));
    if (!(twice_area > tol.degenerate_relative_height * longest2))
      problems.add("degenerate (zero-area) triangles", tri_name(t));
  }

  // Duplicates: sort the triangles by their sorted vertex triples and compare neighbours.
  std::vector<std::pair<Triangle, int>> keyed(nt);
  for (int t = 0; t < nt; ++t) {
    keyed[t] = {s.triangles[t], t};
    std::sort(keyed[t].first.begin(), keyed[t].first.end());
  }
  std::sort(keyed.begin(), keyed.end());
  for (int i = 1; i < nt; ++i)
    if (keyed[i].first == keyed[i - 1].first)
      problems.add("duplicate triangles", tri_name(keyed[i].second) + " repeats " + tri_name(keyed[i - 1].second));

  // Edge incidence: for every undirected edge the triangles using it and the direction.
  struct EdgeUse {
    int tri[2] = {-1, -1};
    int from[2] = {-1, -1};
    int count = 0;
  };
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(static_cast<std::size_t>(nt) * 2);
  for (int t = 0; t < nt; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
      EdgeUse& e = edges[edge_key(a, b)];
      if (e.count < 2) {
        e.tri[e.count] = t;
        e.from[e.count] = a;
      }
      ++e.count;
    }
  }
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  int n_boundary_edges = 0;
  for (const auto& [key, e] : edges) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    const std::string edge = "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
    if (e.count > 2) {
      problems.add("non-manifold edges", edge + " is shared by " + std::to_string(e.count) + " triangles");
    } else if (e.count == 1) {
      ++n_boundary_edges;
      if (!opt.allow_open)
        problems.add("open boundary edges (holes)", edge + " of " + tri_name(e.tri[0]) + " has no neighbour");
    } else {
      if (e.from[0] == e.from[1])
        problems.add("inconsistent orientation",
                     tri_name(e.tri[0]) + " and " + tri_name(e.tri[1]) + " run the same way along " + edge);
      parent[find_root(parent, e.tri[0])] = find_root(parent, e.tri[1]);
    }
  }
  problems.raise_if_any();

  std::vector<char> used(nv, 0);
  for (const Triangle& t : s.triangles)
    for (int v : t) used[v] = 1;
  for (int v = 0; v < nv; ++v)
    if (!used[v]) problems.add("unused vertices", "vertex " + std::to_string(v) + " is used by no triangle");
  const VertexFans fans = build_vertex_fans(s);
  for (int v : fans.non_manifold)
    problems.add("non-manifold vertices",
                 "vertex " + std::to_string(v) + " at " + fmt_point(s.points[v]) +
                     ": its triangles form more than one fan (surfaces touching at a point)");
  problems.raise_if_any();

  // Orientation per connected component.
  std::vector<int> comp_of_root(nt, -1);
  std::vector<int> comp(nt);
  for (int t = 0; t < nt; ++t) {
    const int r = find_root(parent, t);
    if (comp_of_root[r] < 0) comp_of_root[r] = out.n_components++;
    comp[t] = comp_of_root[r];
  }
  std::vector<char> comp_open(out.n_components, 0);
  for (const auto& [key, e] : edges)
    if (e.count == 1) comp_open[comp[e.tri[0]]] = 1;
  std::vector<double> volume(out.n_components, 0.0);
  Vec3 centre{0, 0, 0};
  for (const Vec3& p : s.points) centre += p;
  centre = centre / static_cast<double>(nv);
  for (int t = 0; t < nt; ++t) {
    const Triangle& tr = s.triangles[t];
    const Vec3 a = s.points[tr[0]] - centre, b = s.points[tr[1]] - centre, c = s.points[tr[2]] - centre;
    volume[comp[t]] += dot(a, cross(b, c)) / 6.0;
  }
  const double diag = bounding_box_diagonal(s.points);
  out.closed = n_boundary_edges == 0;
  std::vector<char> flip(out.n_components, 0);
  for (int c = 0; c < out.n_components; ++c) {
    if (comp_open[c]) {
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
  for (int t = 0; t < nt; ++t)
    if (flip[comp[t]]) std::swap(s.triangles[t][1], s.triangles[t][2]);
  for (int c = 0; c < out.n_components; ++c) {
    if (!flip[c]) continue;
    ++out.n_flipped_components;
    if (comp_open[c])
      out.notes.push_back("open component " + std::to_string(c) + ": winding reversed for --side inward");
    else
      out.notes.push_back(std::string("closed component ") + std::to_string(c) + " was oriented " +
                          (volume[c] > 0 ? "outward" : "inward") + "; flipped so that layers grow " +
                          (opt.side == Side::kOutward ? "outward (external flow)" : "inward (internal flow)"));
  }
  if (!out.closed)
    out.notes.push_back("open surface (" + std::to_string(n_boundary_edges) +
                        " boundary edges): layers grow on the side the triangles' normals point to");
  return out;
}

PreparedSurface load_surface(const std::string& path, const PrepareOptions& opt, const Tolerances& tol) {
  return prepare_surface(read_polygon_soup(path), path, opt, tol);
}

}  // namespace blayer
