#include "blayer/fill/tet_fill.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>

#include "blayer/core/errors.h"
#include "blayer/core/tolerances.h"
#include "blayer/fill/run_isolated.h"
#include "size_field.h"
#include "tetgen_adapter.h"

namespace blayer {
namespace {

using fill_detail::SizeField;
using fill_detail::TetgenMesh;
using fill_detail::TetgenPlc;

constexpr double kPi = 3.14159265358979323846;

// Circumradius of a regular tet of edge 1: TetGen's m switch bounds circumradii, the
// size field speaks of edge lengths.
constexpr double kRegularTetCircumradius = 0.6123724356957945;  // sqrt(6)/4

// Hole seeds are tried at these fractions of sqrt(triangle area) behind a triangle:
// the first that the parity test accepts is used, so a thin body still gets one.
constexpr double kHoleDepths[] = {0.1, 0.01, 0.001};
// Number of the largest triangles of a body tried as hole-seed bases.
constexpr int kHoleCandidates = 16;
// A ray-parity query is redone in another direction when a crossing lies this close
// (barycentric coordinate, or ray parameter relative to the surface size) to an edge,
// a vertex or the start point, where double rounding could count it twice or not at all.
constexpr double kParityMargin = 1e-9;

// Samples per box face side when looking for the smallest target size on the box.
constexpr int kBoxSamples = 9;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string fmt_point(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return s.str();
}

// ---------------------------------------------------------------- surface checks

struct EdgeUse {
  int lo, hi;
  bool forward;  // used as lo -> hi
  int triangle;
};

// Throws unless s is a closed, edge-manifold, consistently oriented surface of valid,
// non-degenerate triangles with finite points. `what` names it in messages.
void check_closed_surface(const TriSurface& s, const std::string& what) {
  if (s.triangles.empty()) throw InputError(what + " has no triangles");
  const int np = static_cast<int>(s.points.size());
  const double rel_height = default_tolerances().degenerate_relative_height;
  std::vector<EdgeUse> edges;
  edges.reserve(3 * s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Triangle& tri = s.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] < 0 || tri[k] >= np)
        throw InputError(what + " triangle " + std::to_string(t) + " refers to point " +
                         std::to_string(tri[k]) + ", outside [0, " + std::to_string(np) + ")");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw InputError(what + " triangle " + std::to_string(t) + " repeats a point");
    double longest2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      if (!is_finite(s.points[tri[k]]))
        throw InputError(what + " point " + std::to_string(tri[k]) + " is not finite");
      longest2 = std::max(longest2, norm2(s.points[tri[(k + 1) % 3]] - s.points[tri[k]]));
    }
    if (norm(triangle_area_vector(s, tri)) <= rel_height * longest2)
      throw InputError(what + " triangle " + std::to_string(t) + " is degenerate (zero area) at " +
                       fmt_point(s.points[tri[0]]) + "; remove slivers before the fill");
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<int>(t)});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi;
  });
  std::size_t n_open = 0, n_nonmanifold = 0, n_flipped = 0;
  std::string first_problem;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    int forward = 0;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) {
      forward += edges[j].forward ? 1 : 0;
      ++j;
    }
    const std::size_t count = j - i;
    std::string problem;
    if (count == 1) {
      ++n_open;
      problem = "boundary edge";
    } else if (count > 2) {
      ++n_nonmanifold;
      problem = "edge shared by " + std::to_string(count) + " triangles";
    } else if (forward != 1) {
      ++n_flipped;
      problem = "edge whose two triangles have opposite orientation";
    }
    if (!problem.empty() && first_problem.empty())
      first_problem = problem + " (" + std::to_string(edges[i].lo) + ", " +
                      std::to_string(edges[i].hi) + ") at " + fmt_point(s.points[edges[i].lo]) +
                      ", triangle " + std::to_string(edges[i].triangle);
    i = j;
  }
  if (n_open > 0)
    throw InputError(what + " is open: " + std::to_string(n_open) + " boundary edges, first: " +
                     first_problem + "; the tet fill needs a closed surface");
  if (n_nonmanifold > 0)
    throw InputError(what + " is not edge-manifold: " + std::to_string(n_nonmanifold) +
                     " edges with more than two triangles, first: " + first_problem);
  if (n_flipped > 0)
    throw InputError(what + " is not consistently oriented: " + std::to_string(n_flipped) +
                     " edges, first: " + first_problem);
}

// Connected components over shared edges (vertices suffice for a closed manifold
// surface whose components do not touch; touching ones merge, which only makes the
// orientation test coarser). comp[t] in [0, n).
int triangle_components(const TriSurface& s, std::vector<int>& comp) {
  std::vector<int> parent(s.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Triangle& t : s.triangles) {
    const int r0 = find(t[0]);
    for (int k = 1; k < 3; ++k) {
      const int r = find(t[k]);
      if (r != r0) parent[r] = r0;
    }
  }
  std::vector<int> label(s.points.size(), -1);
  int n = 0;
  comp.resize(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const int r = find(s.triangles[t][0]);
    if (label[r] < 0) label[r] = n++;
    comp[t] = label[r];
  }
  return n;
}

// ---------------------------------------------------------------- ray parity

// Number of triangles of s crossed by the ray from p along dir, or -1 when a crossing
// is too close to an edge, vertex or p to be counted reliably.
int ray_crossings(const TriSurface& s, const Vec3& p, const Vec3& dir, double length_scale) {
  int count = 0;
  for (const Triangle& t : s.triangles) {
    const Vec3& a = s.points[t[0]];
    const Vec3 e1 = s.points[t[1]] - a, e2 = s.points[t[2]] - a;
    const Vec3 q = cross(dir, e2);
    const double det = dot(e1, q);
    const Vec3 r = p - a;
    const double u_num = dot(r, q);
    const Vec3 w = cross(r, e1);
    const double v_num = dot(dir, w);
    const double t_num = dot(e2, w);
    if (det == 0.0) {
      // Ray parallel to the triangle's plane: harmless unless it lies in it.
      if (std::abs(dot(r, cross(e1, e2))) <= kParityMargin * norm(cross(e1, e2)) * length_scale)
        return -1;
      continue;
    }
    const double u = u_num / det, v = v_num / det, tt = t_num / det;
    if (u < -kParityMargin || v < -kParityMargin || u + v > 1.0 + kParityMargin) continue;
    if (tt < -kParityMargin * length_scale) continue;
    if (u < kParityMargin || v < kParityMargin || u + v > 1.0 - kParityMargin ||
        tt < kParityMargin * length_scale)
      return -1;
    ++count;
  }
  return count;
}

// Parity of crossings (true: odd, inside a closed surface), or -1 when undecided.
int inside_parity(const TriSurface& s, const Vec3& p, double length_scale) {
  // Directions with no simple rational relation to coordinate axes, so grid-aligned
  // input rarely puts a ray through an edge.
  static const Vec3 kDirs[] = {{0.5773, 0.6133, 0.5391},
                               {-0.3187, 0.8419, 0.4357},
                               {0.7071, -0.2113, -0.6747},
                               {-0.6019, -0.5023, 0.6213},
                               {0.1234, 0.4321, -0.8932}};
  for (const Vec3& d : kDirs) {
    const int c = ray_crossings(s, p, normalized(d), length_scale);
    if (c >= 0) return c % 2;
  }
  return -1;
}

// ---------------------------------------------------------------- farfield box

struct Farfield {
  TriSurface surface;  // normals into the domain
};

Farfield make_box(const Vec3& lo_env, const Vec3& hi_env, double scale, const SizeField& size,
                  double& spacing) {
  Vec3 extent = hi_env - lo_env;
  const double emax = std::max({extent[0], extent[1], extent[2]});
  Vec3 centre = 0.5 * (lo_env + hi_env), half;
  for (int k = 0; k < 3; ++k) half[k] = 0.5 * scale * std::max(extent[k], 0.5 * emax);
  const Vec3 lo = centre - half, hi = centre + half;

  // Smallest target size over the box surface, sampled on each face.
  spacing = std::numeric_limits<double>::max();
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < kBoxSamples; ++i)
        for (int j = 0; j < kBoxSamples; ++j) {
          Vec3 x;
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          x[axis] = side ? hi[axis] : lo[axis];
          x[u] = lo[u] + (hi[u] - lo[u]) * i / (kBoxSamples - 1);
          x[v] = lo[v] + (hi[v] - lo[v]) * j / (kBoxSamples - 1);
          spacing = std::min(spacing, size(x));
        }
  int n[3];
  for (int k = 0; k < 3; ++k)
    n[k] = std::max(1, static_cast<int>(std::ceil(2.0 * half[k] / spacing)));

  // Lattice points on the box surface, numbered in lattice order.
  Farfield f;
  auto key = [&](int i, int j, int k) {
    return (static_cast<long>(i) * (n[1] + 1) + j) * (n[2] + 1) + k;
  };
  std::vector<int> id(static_cast<std::size_t>((n[0] + 1)) * (n[1] + 1) * (n[2] + 1), -1);
  for (int i = 0; i <= n[0]; ++i)
    for (int j = 0; j <= n[1]; ++j)
      for (int k = 0; k <= n[2]; ++k) {
        if (i != 0 && i != n[0] && j != 0 && j != n[1] && k != 0 && k != n[2]) continue;
        id[key(i, j, k)] = static_cast<int>(f.surface.points.size());
        // End points are set exactly so that the faces meet in identical points.
        auto coord = [&](int a, int idx) {
          return idx == n[a] ? hi[a] : lo[a] + (hi[a] - lo[a]) * idx / n[a];
        };
        f.surface.points.push_back({coord(0, i), coord(1, j), coord(2, k)});
      }
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Vec3 inward{0, 0, 0};
      inward[axis] = side ? -1.0 : 1.0;
      for (int a = 0; a < n[u]; ++a)
        for (int b = 0; b < n[v]; ++b) {
          int c[4];
          for (int q = 0; q < 4; ++q) {
            int idx[3];
            idx[axis] = side ? n[axis] : 0;
            idx[u] = a + (q == 1 || q == 2);
            idx[v] = b + (q >= 2);
            c[q] = id[key(idx[0], idx[1], idx[2])];
          }
          // Alternate diagonals so that the faces carry no preferred direction.
          Triangle t1{c[0], c[1], c[2]}, t2{c[0], c[2], c[3]};
          if ((a + b) % 2 == 1) {
            t1 = {c[0], c[1], c[3]};
            t2 = {c[1], c[2], c[3]};
          }
          for (Triangle t : {t1, t2}) {
            if (dot(triangle_area_vector(f.surface, t), inward) < 0) std::swap(t[1], t[2]);
            f.surface.triangles.push_back(t);
          }
        }
    }
  }
  return f;
}

// ---------------------------------------------------------------- output checks

struct FaceRef {
  std::array<std::int64_t, 3> key;  // sorted point indices
  std::int64_t tet;
};

std::array<std::int64_t, 3> sorted_key(std::int64_t a, std::int64_t b, std::int64_t c) {
  std::array<std::int64_t, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

// Parity of the permutation that takes `nodes` to (a, b, c, d).
bool even_permutation(const std::int64_t* nodes, const std::array<std::int64_t, 4>& order) {
  int pos[4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (nodes[j] == order[i]) pos[i] = j;
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += pos[i] > pos[j];
  return inversions % 2 == 0;
}

double det3(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(cross(b - a, c - a), d - a);
}

// Dihedral angles and radius-edge ratio of one tet.
void tet_quality(const Vec3* p, double& min_dihedral, double& radius_edge) {
  static const int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  Vec3 n[4];
  for (int f = 0; f < 4; ++f)
    n[f] = normalized(cross(p[kFaces[f][1]] - p[kFaces[f][0]], p[kFaces[f][2]] - p[kFaces[f][0]]));
  min_dihedral = kPi;
  for (int f = 0; f < 4; ++f)
    for (int g = f + 1; g < 4; ++g)
      min_dihedral = std::min(min_dihedral, kPi - angle_between(n[f], n[g]));
  // Circumcentre relative to p0: solve 2 [a; b; c] x = [|a|^2; |b|^2; |c|^2].
  const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double det = dot(a, cross(b, c));
  const Vec3 x =
      (norm2(a) * cross(b, c) + norm2(b) * cross(c, a) + norm2(c) * cross(a, b)) / (2.0 * det);
  double shortest = std::numeric_limits<double>::max();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, norm(p[i] - p[j]));
  radius_edge = norm(x) / shortest;
}

std::string tetgen_failure(const IsolatedOutcome& o) {
  if (o.kind == IsolatedOutcome::Kind::kThrewInt)
    return fill_detail::describe_tetgen_error(o.thrown_int);
  return o.data;
}

}  // namespace

FillResult fill_with_tets(const TriSurface& envelope, const FillOptions& opt) {
  const auto t_start = Clock::now();
  using Region = FillOptions::Region;
  const bool outside = opt.region == Region::kOutside;

  if (!(opt.growth >= 1.0) || !std::isfinite(opt.growth))
    throw InputError("fill: growth must be >= 1, got " + std::to_string(opt.growth));
  if (!(opt.quality_radius_edge > 1.0) || !std::isfinite(opt.quality_radius_edge))
    throw InputError(
        "fill: quality_radius_edge must be > 1 (TetGen does not terminate below), got " +
        std::to_string(opt.quality_radius_edge));
  if (!(opt.envelope_size >= 0.0) || !std::isfinite(opt.envelope_size))
    throw InputError("fill: envelope_size must be >= 0, got " + std::to_string(opt.envelope_size));
  if (opt.max_steiner_points < 0) throw InputError("fill: max_steiner_points must be >= 0");
  if (outside && !opt.farfield && !(opt.farfield_scale > 1.0 && std::isfinite(opt.farfield_scale)))
    throw InputError("fill: farfield_scale must be > 1, got " + std::to_string(opt.farfield_scale));
  if (!outside && opt.farfield)
    throw InputError("fill: a farfield surface is only used with region outside (external flow)");

  check_closed_surface(envelope, "envelope");

  // Points used by the envelope, in their original order; TetGen sees only these.
  const std::int64_t n_env = static_cast<std::int64_t>(envelope.points.size());
  std::vector<int> env_local(envelope.points.size(), -1);
  std::vector<int> env_used;
  for (const Triangle& t : envelope.triangles)
    for (int v : t) env_local[v] = 0;
  for (std::size_t i = 0; i < envelope.points.size(); ++i)
    if (env_local[i] == 0) {
      env_local[i] = static_cast<int>(env_used.size());
      env_used.push_back(static_cast<int>(i));
    }

  Vec3 lo = envelope.points[env_used[0]], hi = lo;
  for (int i : env_used)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], envelope.points[i][k]);
      hi[k] = std::max(hi[k], envelope.points[i][k]);
    }
  const double diag = norm(hi - lo);

  // Orientation per component decides bodies (hole seeds) and walls.
  std::vector<int> comp;
  const int n_comp = triangle_components(envelope, comp);
  std::vector<double> comp_volume(n_comp, 0.0);
  const Vec3 ref = 0.5 * (lo + hi);
  for (std::size_t t = 0; t < envelope.triangles.size(); ++t) {
    const Triangle& tri = envelope.triangles[t];
    comp_volume[comp[t]] +=
        dot(envelope.points[tri[0]] - ref,
            cross(envelope.points[tri[1]] - ref, envelope.points[tri[2]] - ref)) /
        6.0;
  }
  int n_walls = 0;
  for (int c = 0; c < n_comp; ++c) {
    if (comp_volume[c] < 0.0) {
      ++n_walls;
      if (outside)
        throw InputError("envelope component " + std::to_string(c) + " encloses negative volume (" +
                         std::to_string(comp_volume[c]) +
                         "): its normals point into its body. For internal flow use region inside "
                         "(--side inward); otherwise the envelope is inverted");
    } else if (comp_volume[c] == 0.0) {
      throw InputError("envelope component " + std::to_string(c) + " encloses zero volume");
    }
  }
  if (!outside && n_walls == 0)
    throw InputError(
        "fill region inside: no envelope component has normals pointing into an "
        "enclosed volume; the envelope faces outward, use region outside (external flow)");

  // Size field from the envelope's local edge lengths.
  std::vector<double> h_env(envelope.points.size(), 0.0);
  if (opt.envelope_size > 0.0) {
    for (int i : env_used) h_env[i] = opt.envelope_size;
  } else {
    std::vector<int> count(envelope.points.size(), 0);
    for (const Triangle& t : envelope.triangles)
      for (int k = 0; k < 3; ++k) {
        const double l = norm(envelope.points[t[(k + 1) % 3]] - envelope.points[t[k]]);
        // Each edge appears in two triangles; both ends get it once from each side.
        h_env[t[k]] += l;
        h_env[t[(k + 1) % 3]] += l;
        count[t[k]] += 1;
        count[t[(k + 1) % 3]] += 1;
      }
    for (int i : env_used) h_env[i] /= count[i];
  }
  std::vector<Vec3> sites;
  std::vector<double> site_sizes;
  for (int i : env_used) {
    sites.push_back(envelope.points[i]);
    site_sizes.push_back(h_env[i]);
  }
  const SizeField size(sites, site_sizes, opt.growth - 1.0);

  FillResult result;
  FillStats& st = result.stats;
  st.n_envelope_points = n_env;
  st.min_envelope_size = *std::min_element(site_sizes.begin(), site_sizes.end());
  st.max_envelope_size = *std::max_element(site_sizes.begin(), site_sizes.end());

  // Farfield, wound with normals into the domain.
  TriSurface far;
  if (outside) {
    if (opt.farfield) {
      check_closed_surface(*opt.farfield, "farfield");
      far = *opt.farfield;
      const double v = signed_volume(far);
      if (v > 0.0)
        for (Triangle& t : far.triangles) std::swap(t[1], t[2]);
      for (int c = 0; c < n_comp; ++c) {
        const int t = static_cast<int>(std::find(comp.begin(), comp.end(), c) - comp.begin());
        const Vec3& p = envelope.points[envelope.triangles[t][0]];
        if (inside_parity(far, p, bounding_box_diagonal(far.points)) != 1)
          throw InputError("farfield does not enclose envelope component " + std::to_string(c) +
                           " (its point " + fmt_point(p) + " is outside or on the farfield)");
      }
      double far_size = 0.0;
      for (const Vec3& p : far.points) far_size = std::max(far_size, size(p));
      st.farfield_size = far_size;
    } else {
      Farfield box = make_box(lo, hi, opt.farfield_scale, size, st.farfield_size);
      far = std::move(box.surface);
    }
  }
  // Compact the farfield's points too (a user surface may carry unused ones).
  std::vector<int> far_local(far.points.size(), -1);
  std::vector<int> far_used;
  for (const Triangle& t : far.triangles)
    for (int v : t) far_local[v] = 0;
  for (std::size_t i = 0; i < far.points.size(); ++i)
    if (far_local[i] == 0) {
      far_local[i] = static_cast<int>(far_used.size());
      far_used.push_back(static_cast<int>(i));
    }
  st.n_farfield_points = static_cast<std::int64_t>(far.points.size());

  // The PLC, with TetGen-local point indices: used envelope points, then used farfield points.
  TetgenPlc plc;
  std::vector<Vec3> local_points;
  for (int i : env_used) local_points.push_back(envelope.points[i]);
  for (int i : far_used) local_points.push_back(far.points[i]);
  const int n_local_env = static_cast<int>(env_used.size());
  {
    std::vector<int> idx(local_points.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::sort(idx.begin(), idx.end(),
              [&](int a, int b) { return local_points[a] < local_points[b]; });
    for (std::size_t i = 1; i < idx.size(); ++i)
      if (local_points[idx[i]] == local_points[idx[i - 1]])
        throw InputError("two boundary points coincide at " + fmt_point(local_points[idx[i]]) +
                         "; merge duplicate points before the fill");
  }
  for (const Vec3& p : local_points) plc.points.insert(plc.points.end(), p.begin(), p.end());
  for (const Triangle& t : envelope.triangles) {
    for (int v : t) plc.triangles.push_back(env_local[v]);
    plc.markers.push_back(kEnvelopeMarker);
  }
  for (const Triangle& t : far.triangles) {
    for (int v : t) plc.triangles.push_back(n_local_env + far_local[v]);
    plc.markers.push_back(kFarfieldMarker);
  }

  const std::size_t n_boundary = envelope.triangles.size() + far.triangles.size();
  auto describe_local_face = [&](const std::array<int, 3>& f) {
    std::array<int, 3> k = f;
    std::sort(k.begin(), k.end());
    for (std::size_t t = 0; t < n_boundary; ++t) {
      std::array<int, 3> g{plc.triangles[3 * t], plc.triangles[3 * t + 1],
                           plc.triangles[3 * t + 2]};
      std::sort(g.begin(), g.end());
      if (g == k) {
        const bool env = t < envelope.triangles.size();
        const std::size_t id = env ? t : t - envelope.triangles.size();
        const Vec3 c = (local_points[f[0]] + local_points[f[1]] + local_points[f[2]]) / 3.0;
        return std::string(env ? "envelope" : "farfield") + " triangle " + std::to_string(id) +
               " near " + fmt_point(c);
      }
    }
    return std::string("a triangle TetGen created");
  };

  // Self-intersection check in its own child: d stops after the surface stage and
  // returns only the intersecting faces.
  {
    const auto t0 = Clock::now();
    IsolatedOutcome o;
    try {
      o = run_isolated([&plc] { return fill_detail::encode(fill_detail::run_tetgen(plc, "pdQ")); },
                       opt.timeout_seconds);
    } catch (const ChildProcessError& e) {
      throw InputError(std::string("tetgen failed during the self-intersection check: ") +
                       e.what() + "; check the envelope for self-intersections and slivers");
    }
    if (o.kind != IsolatedOutcome::Kind::kOk)
      throw InputError("tetgen failed during the self-intersection check: " + tetgen_failure(o));
    const TetgenMesh d = fill_detail::decode(o.data);
    if (!d.faces.empty()) {
      std::string list;
      const std::size_t n_show = std::min<std::size_t>(3, d.faces.size() / 3);
      for (std::size_t i = 0; i < n_show; ++i)
        list += (i ? "; " : "") +
                describe_local_face({d.faces[3 * i], d.faces[3 * i + 1], d.faces[3 * i + 2]});
      throw InputError("the boundary intersects itself: " + std::to_string(d.faces.size() / 3) +
                       " intersecting triangles, e.g. " + list +
                       "; lower the layer thickness or fix the surface before the fill");
    }
    st.seconds_check = seconds_since(t0);
  }

  // Hole seeds: one per body component, verified by ray parity against the envelope
  // (meaningful only now that the boundary is known not to intersect itself).
  std::vector<Vec3> holes;
  for (int c = 0; c < n_comp; ++c) {
    if (comp_volume[c] < 0.0) continue;
    std::vector<int> tris;
    for (std::size_t t = 0; t < envelope.triangles.size(); ++t)
      if (comp[t] == c) tris.push_back(static_cast<int>(t));
    const int n_try = std::min<int>(kHoleCandidates, static_cast<int>(tris.size()));
    std::partial_sort(tris.begin(), tris.begin() + n_try, tris.end(), [&](int a, int b) {
      return norm2(triangle_area_vector(envelope, envelope.triangles[a])) >
             norm2(triangle_area_vector(envelope, envelope.triangles[b]));
    });
    bool found = false;
    for (int i = 0; i < n_try && !found; ++i) {
      const Triangle& tri = envelope.triangles[tris[i]];
      const Vec3 area2 = triangle_area_vector(envelope, tri);
      const Vec3 centroid =
          (envelope.points[tri[0]] + envelope.points[tri[1]] + envelope.points[tri[2]]) / 3.0;
      const double size = std::sqrt(0.5 * norm(area2));
      for (double depth : kHoleDepths) {
        const Vec3 seed = centroid - (depth * size) * normalized(area2);
        const int parity = inside_parity(envelope, seed, diag);
        // Not in the fill region: inside a body for outside, even parity for inside.
        const bool in_body = outside ? parity == 1 : parity == 0;
        if (parity >= 0 && in_body) {
          holes.push_back(seed);
          found = true;
          break;
        }
      }
    }
    if (!found)
      throw InputError("envelope component " + std::to_string(c) +
                       ": found no point inside its body for TetGen's hole seed (ray-parity tests "
                       "disagree); the envelope is probably self-intersecting or nested");
  }

  for (const Vec3& h : holes) plc.holes.insert(plc.holes.end(), h.begin(), h.end());
  st.n_holes = static_cast<std::int64_t>(holes.size());

  // Point metrics: circumradius bounds from the size field.
  for (const Vec3& p : local_points) plc.point_metric.push_back(kRegularTetCircumradius * size(p));

  std::ostringstream sw;
  sw << "pYq" << opt.quality_radius_edge << "mQ";
  if (opt.max_steiner_points > 0) sw << "S" << opt.max_steiner_points;
  const std::string switches = sw.str();

  TetgenMesh mesh;
  {
    const auto t0 = Clock::now();
    IsolatedOutcome o;
    try {
      o = run_isolated(
          [&plc, &switches] { return fill_detail::encode(fill_detail::run_tetgen(plc, switches)); },
          opt.timeout_seconds);
    } catch (const ChildProcessError& e) {
      throw InputError(std::string("tetgen failed: ") + e.what() +
                       "; check the envelope for slivers and near-touching parts");
    }
    if (o.kind != IsolatedOutcome::Kind::kOk)
      throw InputError("tetgen failed: " + tetgen_failure(o));
    try {
      mesh = fill_detail::decode(o.data);
    } catch (const std::exception& e) {
      throw InputError(std::string("tetgen failed: ") + e.what());
    }
    st.seconds_tetgen = seconds_since(t0);
  }

  // Points: the input points must come back first, unchanged.
  const std::int64_t n_out = static_cast<std::int64_t>(mesh.points.size() / 3);
  if (n_out < static_cast<std::int64_t>(local_points.size()))
    throw InputError("tetgen failed: it returned fewer points than it was given");
  for (std::size_t i = 0; i < local_points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (mesh.points[3 * i + k] != local_points[i][k])
        throw InputError("tetgen failed: input point " + std::to_string(i) +
                         " came back moved or reordered");

  // TetGen-local index -> output index.
  const std::int64_t n_far_out = static_cast<std::int64_t>(far.points.size());
  std::vector<std::int64_t> to_out(static_cast<std::size_t>(n_out));
  for (int i = 0; i < n_local_env; ++i) to_out[i] = env_used[i];
  for (std::size_t i = 0; i < far_used.size(); ++i) to_out[n_local_env + i] = n_env + far_used[i];
  const std::int64_t n_steiner = n_out - static_cast<std::int64_t>(local_points.size());
  for (std::int64_t i = 0; i < n_steiner; ++i)
    to_out[local_points.size() + i] = n_env + n_far_out + i;

  VolumeMesh& vm = result.tets;
  vm.points = envelope.points;
  vm.points.insert(vm.points.end(), far.points.begin(), far.points.end());
  for (std::int64_t i = 0; i < n_steiner; ++i) {
    const std::size_t j = 3 * (local_points.size() + i);
    vm.points.push_back({mesh.points[j], mesh.points[j + 1], mesh.points[j + 2]});
  }

  // Orientation: TetGen's tets all have one (exactly computed) orientation; find it from
  // the tet with the largest |volume|, where double rounding cannot flip the sign.
  const std::int64_t n_tets = static_cast<std::int64_t>(mesh.tets.size() / 4);
  if (n_tets == 0) throw InputError("tetgen failed: it returned no tetrahedra");
  std::vector<std::int64_t> conn(mesh.tets.size());
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    if (mesh.tets[i] < 0 || mesh.tets[i] >= n_out)
      throw InputError("tetgen failed: a tetrahedron refers to a point it did not return");
    conn[i] = to_out[mesh.tets[i]];
  }
  auto tet_det = [&](std::int64_t t) {
    const std::int64_t* c = &conn[4 * t];
    return det3(vm.points[c[0]], vm.points[c[1]], vm.points[c[2]], vm.points[c[3]]);
  };
  std::int64_t largest = 0;
  for (std::int64_t t = 1; t < n_tets; ++t)
    if (std::abs(tet_det(t)) > std::abs(tet_det(largest))) largest = t;
  if (tet_det(largest) < 0.0)
    for (std::int64_t t = 0; t < n_tets; ++t) std::swap(conn[4 * t + 1], conn[4 * t + 2]);

  vm.cell_types.assign(static_cast<std::size_t>(n_tets), CellType::kTet);
  vm.offsets.resize(static_cast<std::size_t>(n_tets) + 1);
  for (std::int64_t t = 0; t <= n_tets; ++t) vm.offsets[t] = 4 * t;
  vm.connectivity = conn;

  // Boundary: envelope then farfield triangles, output indices.
  result.boundary.points = vm.points;
  for (const Triangle& t : envelope.triangles) {
    result.boundary.triangles.push_back(t);
    result.boundary_marker.push_back(kEnvelopeMarker);
  }
  for (const Triangle& t : far.triangles) {
    result.boundary.triangles.push_back({t[0] + static_cast<int>(n_env),
                                         t[1] + static_cast<int>(n_env),
                                         t[2] + static_cast<int>(n_env)});
    result.boundary_marker.push_back(kFarfieldMarker);
  }

  // Conformity: faces used once are exactly the boundary triangles, none more than twice.
  {
    std::vector<FaceRef> faces;
    faces.reserve(4 * static_cast<std::size_t>(n_tets));
    static const int kOpp[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (std::int64_t t = 0; t < n_tets; ++t)
      for (const auto& f : kOpp)
        faces.push_back(
            {sorted_key(conn[4 * t + f[0]], conn[4 * t + f[1]], conn[4 * t + f[2]]), t});
    std::sort(faces.begin(), faces.end(),
              [](const FaceRef& a, const FaceRef& b) { return a.key < b.key; });
    std::vector<FaceRef> single;
    for (std::size_t i = 0; i < faces.size();) {
      std::size_t j = i;
      while (j < faces.size() && faces[j].key == faces[i].key) ++j;
      if (j - i > 2)
        throw InputError("tetgen failed: the tet mesh is not conforming (a face shared by " +
                         std::to_string(j - i) + " tets)");
      if (j - i == 1) single.push_back(faces[i]);
      i = j;
    }
    std::vector<std::pair<std::array<std::int64_t, 3>, std::size_t>> bnd;
    for (std::size_t b = 0; b < result.boundary.triangles.size(); ++b) {
      const Triangle& t = result.boundary.triangles[b];
      bnd.push_back({sorted_key(t[0], t[1], t[2]), b});
    }
    std::sort(bnd.begin(), bnd.end());
    std::size_t n_missing = 0;
    std::size_t i = 0, j = 0;
    for (; i < bnd.size(); ++i) {
      while (j < single.size() && single[j].key < bnd[i].first) ++j;
      if (j == single.size() || single[j].key != bnd[i].first) {
        ++n_missing;
        continue;
      }
      // The tet on this boundary triangle must lie on the side its normal points to.
      const Triangle& t = result.boundary.triangles[bnd[i].second];
      const std::int64_t* c = &conn[4 * single[j].tet];
      std::int64_t d = -1;
      for (int k = 0; k < 4; ++k)
        if (c[k] != t[0] && c[k] != t[1] && c[k] != t[2]) d = c[k];
      if (!even_permutation(c, {t[0], t[1], t[2], d}))
        throw InputError("tet fill: tets lie on the wrong side of boundary triangle " +
                         std::to_string(bnd[i].second) +
                         "; the hole seeds selected the wrong region");
    }
    if (n_missing > 0 || single.size() != bnd.size())
      throw InputError("tetgen failed: the tets do not conform to the boundary (" +
                       std::to_string(n_missing) + " boundary triangles are not tet faces, " +
                       std::to_string(single.size()) + " faces lie on the mesh boundary for " +
                       std::to_string(bnd.size()) +
                       " boundary triangles); TetGen split the boundary despite the Y switch");
  }

  st.n_steiner_points = n_steiner;
  st.n_tets = n_tets;
  st.min_dihedral_deg = 180.0;
  st.min_dihedral_deg_interior = 180.0;
  st.max_radius_edge = 0.0;
  st.min_tet_volume = std::numeric_limits<double>::max();
  for (std::int64_t t = 0; t < n_tets; ++t) {
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) p[k] = vm.points[conn[4 * t + k]];
    double dihedral, radius_edge;
    tet_quality(p, dihedral, radius_edge);
    st.min_dihedral_deg = std::min(st.min_dihedral_deg, dihedral * 180.0 / kPi);
    bool interior = true;
    for (int k = 0; k < 4; ++k) interior = interior && conn[4 * t + k] >= n_env + n_far_out;
    if (interior)
      st.min_dihedral_deg_interior =
          std::min(st.min_dihedral_deg_interior, dihedral * 180.0 / kPi);
    st.max_radius_edge = std::max(st.max_radius_edge, radius_edge);
    st.min_tet_volume = std::min(st.min_tet_volume, det3(p[0], p[1], p[2], p[3]) / 6.0);
  }
  st.seconds_total = seconds_since(t_start);
  return result;
}

}  // namespace blayer
