#include "blayer/quality/solver_acceptance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "blayer/core/cyclic_index.h"
#include "cell_faces.h"

namespace blayer {

PolyFace reversed(const PolyFace& f) {
  PolyFace r = f;
  std::reverse(r.p.begin(), r.p.begin() + f.n);
  return r;
}

namespace {

// OpenFOAM guards its divisions with ROOTVSMALL = 1e-150 (double builds); the same
// guard keeps the figures equal to the solver's on degenerate faces.
constexpr double kRootVSmall = 1e-150;
constexpr double kRadToDeg = 57.295779513082320876798;

Vec3 point_mean(const PolyFace& f) {
  Vec3 m{0.0, 0.0, 0.0};
  for (int i = 0; i < f.n; ++i) m += f.p[i];
  return m / static_cast<double>(f.n);
}

// Circumradius of the tet (a, b, c, d); infinity when it is flat.
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double den = 2.0 * dot(u, cross(v, w));
  if (std::abs(den) < kRootVSmall) return std::numeric_limits<double>::infinity();
  const Vec3 o = (norm2(u) * cross(v, w) + norm2(v) * cross(w, u) + norm2(w) * cross(u, v)) / den;
  return norm(o);
}

constexpr double kRegularTet = 8.0 / (9.0 * 1.7320508075688772935);  // 8 / (9 sqrt 3)

// tet_quality(a, b, c, d) > tol, without the division and with an early exit on a tet
// that is not positive (tol >= 0).
bool tet_quality_above(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double tol) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const Vec3 vw = cross(v, w);
  const double det = dot(u, vw);  // 6 x the volume
  if (!(det > 0.0)) return false;
  const Vec3 wu = cross(w, u), uv = cross(u, v);
  const Vec3 o2 = norm2(u) * vw + norm2(v) * wu + norm2(w) * uv;  // 2 det x circumcentre - a
  const double r = std::min(norm(o2) / (2.0 * det), 1e15);
  return det / 6.0 > tol * (kRegularTet * r * r * r + kRootVSmall);
}

// Every tet (c, base, p_i, p_i+1) of the fan from `base` above tol; `flip` reverses the
// fan's triangles (the neighbour's side of an internal face).
bool fan_above(const PolyFace& f, int base, const Vec3& c, bool flip, double tol) {
  for (int k = 1; k < f.n - 1; ++k) {
    const Vec3& a = f.p[cyclic_wrap(base + k, f.n)];
    const Vec3& b = f.p[cyclic_wrap(base + k + 1, f.n)];
    if (!(flip ? tet_quality_above(c, f.p[base], b, a, tol) : tet_quality_above(c, f.p[base], a, b, tol))) return false;
  }
  return true;
}

// Every tet (c, Cf, p_i, p_i+1) of the fan about the face centre above tol.
bool centre_fan_above(const PolyFace& f, const Vec3& face_centre, const Vec3& c, double tol) {
  for (int i = 0; i < f.n; ++i)
    if (!tet_quality_above(c, face_centre, f.p[i], f.p[cyclic_next(i, f.n)], tol)) return false;
  return true;
}

// checkMesh's face tets (see the header) with limit tol: OpenFOAM takes the first base
// point that works, so this stops at it too. A triangle's centre-fan tets are the
// thirds of its one base tet (its centre is the centroid), so with a base tet of
// quality above tol >= 1e-12 -- a volume above 6e-14 L^3 for extent L -- each third
// is positive far beyond the 1e-16 L^3 rounding: only the base tet is computed.
bool face_tets_above(const PolyFace& f, const FaceGeometry& g, const Vec3& own, const Vec3* nei, double tol) {
  if (f.n == 3) return fan_above(f, 0, own, false, tol) && (!nei || fan_above(f, 0, *nei, true, tol));
  if (!centre_fan_above(f, g.centre, own, tol)) return false;
  if (nei && !centre_fan_above(reversed(f), g.centre, *nei, tol)) return false;
  for (int base = 0; base < f.n; ++base)
    if (fan_above(f, base, own, false, tol) && (!nei || fan_above(f, base, *nei, true, tol))) return true;
  return false;
}

// Worst tet of the fan from base point `base` about centre c; `flip` reverses the fan's
// triangles (the neighbour's side of an internal face).
double fan_quality(const PolyFace& f, int base, const Vec3& c, bool flip) {
  double worst = std::numeric_limits<double>::infinity();
  for (int k = 1; k < f.n - 1; ++k) {
    const Vec3& a = f.p[cyclic_wrap(base + k, f.n)];
    const Vec3& b = f.p[cyclic_wrap(base + k + 1, f.n)];
    const double q = flip ? tet_quality(c, f.p[base], b, a) : tet_quality(c, f.p[base], a, b);
    worst = std::min(worst, q);
  }
  return worst;
}

// The normalisation of the skewness: the face's extent from Cf along the skew vector's
// direction, at least `floor`.
double skew_extent(const PolyFace& f, const FaceGeometry& g, const Vec3& sv, double floor) {
  const Vec3 dir = sv / (norm(sv) + kRootVSmall);
  double fd = floor + kRootVSmall;
  for (int i = 0; i < f.n; ++i) fd = std::max(fd, std::abs(dot(dir, f.p[i] - g.centre)));
  return fd;
}

// The skew vector: Cf minus the point where the line from `own` along d crosses the
// face's plane.
Vec3 skew_vector(const FaceGeometry& g, const Vec3& own, const Vec3& d) {
  const Vec3 cpf = g.centre - own;
  return cpf - (dot(g.area, cpf) / (dot(g.area, d) + kRootVSmall)) * d;
}

// face_non_orthogonality_deg(g, own, nei) <= limit_deg, compared as cosines.
bool non_orthogonality_within(const FaceGeometry& g, const Vec3& own, const Vec3& nei, double limit_deg) {
  const Vec3 d = nei - own;
  const double c = dot(d, g.area) / (norm(d) * norm(g.area) + kRootVSmall);
  return c >= std::cos(limit_deg / kRadToDeg);
}

}  // namespace

FaceGeometry face_geometry(const PolyFace& f) {
  FaceGeometry g;
  if (f.n == 3) {
    g.centre = (f.p[0] + f.p[1] + f.p[2]) / 3.0;
    g.area = 0.5 * cross(f.p[1] - f.p[0], f.p[2] - f.p[0]);
    return g;
  }
  const Vec3 m = point_mean(f);
  Vec3 sum_n{0.0, 0.0, 0.0}, sum_ac{0.0, 0.0, 0.0};
  double sum_a = 0.0;
  for (int i = 0; i < f.n; ++i) {
    const Vec3& p = f.p[i];
    const Vec3& q = f.p[cyclic_next(i, f.n)];
    const Vec3 n = cross(q - p, m - p);
    const double a = norm(n);
    sum_n += n;
    sum_a += a;
    sum_ac += a * (p + q + m);
  }
  if (sum_a < kRootVSmall) {
    g.centre = m;
    return g;
  }
  g.centre = sum_ac / (3.0 * sum_a);
  g.area = 0.5 * sum_n;
  return g;
}

CellGeometry cell_geometry(const FaceGeometry* faces, int n_faces) {
  Vec3 c0{0.0, 0.0, 0.0};
  for (int i = 0; i < n_faces; ++i) c0 += faces[i].centre;
  c0 = c0 / static_cast<double>(n_faces);
  Vec3 sum_vc{0.0, 0.0, 0.0};
  double sum_v = 0.0;
  for (int i = 0; i < n_faces; ++i) {
    const double v3 = dot(faces[i].area, faces[i].centre - c0);
    sum_vc += v3 * (0.75 * faces[i].centre + 0.25 * c0);
    sum_v += v3;
  }
  CellGeometry g;
  // OpenFOAM's VSMALL (1e-300) guard: a cell of no volume keeps the estimate.
  g.centre = std::abs(sum_v) > 1e-300 ? sum_vc / sum_v : c0;
  g.volume = sum_v / 3.0;
  return g;
}

int cell_poly_faces(CellType type, const Vec3* corners, PolyFace out[6]) {
  const detail::CellFaces& cf = detail::cell_faces(type);
  for (int i = 0; i < cf.n_faces; ++i) {
    out[i].n = cf.faces[i].n;
    for (int k = 0; k < out[i].n; ++k) out[i].p[k] = corners[cf.faces[i].v[k]];
  }
  return cf.n_faces;
}

double face_pyramid_volume(const FaceGeometry& g, const Vec3& cell_centre) {
  return dot(g.area, g.centre - cell_centre) / 3.0;
}

double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double volume = dot(b - a, cross(c - a, d - a)) / 6.0;
  const double r = std::min(circumradius(a, b, c, d), 1e15);  // OpenFOAM caps it at GREAT
  return volume / (kRegularTet * r * r * r + kRootVSmall);
}

double face_tet_quality(const PolyFace& f, const Vec3& own, const Vec3* nei) {
  double best = -std::numeric_limits<double>::infinity();
  for (int base = 0; base < f.n; ++base) {
    double q = fan_quality(f, base, own, false);
    if (nei) q = std::min(q, fan_quality(f, base, *nei, true));
    best = std::max(best, q);
  }
  return best;
}

double face_centre_tet_quality(const PolyFace& f, const FaceGeometry& g, const Vec3& centre) {
  double worst = std::numeric_limits<double>::infinity();
  for (int i = 0; i < f.n; ++i) worst = std::min(worst, tet_quality(centre, g.centre, f.p[i], f.p[cyclic_next(i, f.n)]));
  return worst;
}

double face_non_orthogonality_deg(const FaceGeometry& g, const Vec3& own, const Vec3& nei) {
  const Vec3 d = nei - own;
  const double c = dot(d, g.area) / (norm(d) * norm(g.area) + kRootVSmall);
  return std::acos(std::clamp(c, -1.0, 1.0)) * kRadToDeg;
}

double wall_edge_non_orthogonality_deg(const std::array<Vec3, 3>& f, const std::array<Vec3, 3>& g, const Vec3& a,
                                       const Vec3& b) {
  const Vec3 nf = normalized(cross(f[1] - f[0], f[2] - f[0]));
  const Vec3 ng = normalized(cross(g[1] - g[0], g[2] - g[0]));
  const Vec3 cf = (f[0] + f[1] + f[2]) / 3.0, cg = (g[0] + g[1] + g[2]) / 3.0;
  FaceGeometry face{0.5 * (a + b), cross(b - a, nf + ng)};
  if (dot(face.area, face.centre - cf) < 0.0) face.area = -face.area;  // out of f
  return face_non_orthogonality_deg(face, cf, cg);
}

double inherited_non_orthogonality_limit_deg(double limit_deg, double inherited_deg) {
  if (!(limit_deg > 0.0)) return limit_deg;
  // Below 60 degrees the factor is cos L, not 1/2: a flat wall edge (cosine 1) then
  // widens nothing, where half its cosine would raise every such limit to 60.
  const double factor = std::max(0.5, std::cos(limit_deg / kRadToDeg));
  const double cosine = factor * std::cos(inherited_deg / kRadToDeg);
  const double widened = std::acos(std::max(cosine, kMinNonOrthogonalityCosine)) * kRadToDeg;
  return std::max(limit_deg, widened);
}

double face_skewness(const PolyFace& f, const FaceGeometry& g, const Vec3& own, const Vec3& nei) {
  const Vec3 d = nei - own;
  const Vec3 sv = skew_vector(g, own, d);
  return norm(sv) / skew_extent(f, g, sv, 0.2 * norm(d));
}

double boundary_face_skewness(const PolyFace& f, const FaceGeometry& g, const Vec3& own) {
  const Vec3 n = g.area / (norm(g.area) + kRootVSmall);
  const Vec3 d = dot(n, g.centre - own) * n;
  const Vec3 sv = skew_vector(g, own, d);
  return norm(sv) / skew_extent(f, g, sv, 0.4 * norm(d));
}

double face_flatness(const PolyFace& f, const FaceGeometry& g) {
  const double mag = norm(g.area);
  if (f.n == 3 || mag <= kRootVSmall) return 1.0;
  double sum = 0.0;
  for (int i = 0; i < f.n; ++i) {
    const Vec3& p = f.p[i];
    const Vec3& q = f.p[cyclic_next(i, f.n)];
    sum += 0.5 * norm(cross(q - p, g.centre - p));
  }
  return mag / (sum + kRootVSmall);
}

double face_warp_deg(const PolyFace& f) {
  if (f.n != 4) return 0.0;
  const std::array<Vec3, 4>& p = f.p;
  const Vec3 n0 = cross(p[1] - p[0], p[2] - p[0]), n1 = cross(p[2] - p[0], p[3] - p[0]);  // diagonal 0-2
  const Vec3 n2 = cross(p[2] - p[1], p[3] - p[1]), n3 = cross(p[3] - p[1], p[0] - p[1]);  // diagonal 1-3
  return std::max(angle_between(n0, n1), angle_between(n2, n3)) * kRadToDeg;
}

const char* acceptance_failure_name(AcceptanceFailure f) {
  switch (f) {
    case AcceptanceFailure::kNone: return "none";
    case AcceptanceFailure::kFacePyramid: return "face_pyramid";
    case AcceptanceFailure::kFaceTets: return "face_tets";
    case AcceptanceFailure::kFaceWarp: return "face_warp";
    case AcceptanceFailure::kNonOrthogonality: return "non_orthogonality";
    case AcceptanceFailure::kSkewness: return "skewness";
    case AcceptanceFailure::kBoundarySkewness: return "boundary_skewness";
  }
  return "unknown";
}

AcceptanceFailure judge_face(const PolyFace& f, const FaceGeometry& g, const Vec3& own, FaceSide side,
                             const Vec3& other, const AcceptanceLimits& limits) {
  const bool internal = side == FaceSide::kInternal;
  if (limits.face_pyramids) {
    if (!(face_pyramid_volume(g, own) > 0.0)) return AcceptanceFailure::kFacePyramid;
    if (internal && !(-face_pyramid_volume(g, other) > 0.0)) return AcceptanceFailure::kFacePyramid;
  }
  if (limits.face_tets && !face_tets_above(f, g, own, internal ? &other : nullptr, kMinFaceTetQuality))
    return AcceptanceFailure::kFaceTets;
  if (limits.max_face_warp_deg > 0.0 && f.n == 4 && !(face_warp_deg(f) <= limits.max_face_warp_deg))
    return AcceptanceFailure::kFaceWarp;
  if (internal) {
    if (limits.max_non_orthogonality_deg > 0.0 &&
        !non_orthogonality_within(g, own, other, limits.max_non_orthogonality_deg))
      return AcceptanceFailure::kNonOrthogonality;
    if (limits.max_skewness > 0.0 && !(face_skewness(f, g, own, other) <= limits.max_skewness))
      return AcceptanceFailure::kSkewness;
  } else if (side == FaceSide::kBoundary && limits.max_boundary_skewness > 0.0 &&
             !(boundary_face_skewness(f, g, own) <= limits.max_boundary_skewness)) {
    return AcceptanceFailure::kBoundarySkewness;
  }
  return AcceptanceFailure::kNone;
}

AcceptanceFailure judge_lone_cell(CellType type, const Vec3* corners, const AcceptanceLimits& limits) {
  PolyFace faces[6];
  FaceGeometry geo[6];
  const int n = cell_poly_faces(type, corners, faces);
  for (int i = 0; i < n; ++i) geo[i] = face_geometry(faces[i]);
  const Vec3 c = cell_geometry(geo, n).centre;
  for (int i = 0; i < n; ++i) {
    const AcceptanceFailure why = judge_face(faces[i], geo[i], c, FaceSide::kBoundary, c, limits);
    if (why != AcceptanceFailure::kNone) return why;
  }
  return AcceptanceFailure::kNone;
}

}  // namespace blayer
