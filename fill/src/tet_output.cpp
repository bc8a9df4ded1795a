#include "tet_output.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"
#include "blayer/core/triangle_ids.h"

namespace blayer::fill_detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct FaceRef {
  TriangleKey key;
  std::int64_t tet;
};

// Parity of the permutation that takes `nodes` to `order`.
bool even_permutation(const PointId* nodes, const std::array<std::int64_t, 4>& order) {
  int pos[4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (nodes[j] == order[i]) pos[i] = j;
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += pos[i] > pos[j];
  return inversions % 2 == 0;
}

double det3(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return dot(cross(b - a, c - a), d - a); }

// Dihedral angles and radius-edge ratio of one tet.
void tet_quality(const Vec3* p, double& min_dihedral, double& radius_edge) {
  static const int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  Vec3 n[4];
  for (int f = 0; f < 4; ++f)
    n[f] = normalized(cross(p[kFaces[f][1]] - p[kFaces[f][0]], p[kFaces[f][2]] - p[kFaces[f][0]]));
  min_dihedral = kPi;
  for (int f = 0; f < 4; ++f)
    for (int g = f + 1; g < 4; ++g) min_dihedral = std::min(min_dihedral, kPi - angle_between(n[f], n[g]));
  // Circumcentre relative to p0: solve 2 [a; b; c] x = [|a|^2; |b|^2; |c|^2].
  const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double det = dot(a, cross(b, c));
  const Vec3 x = (norm2(a) * cross(b, c) + norm2(b) * cross(c, a) + norm2(c) * cross(a, b)) / (2.0 * det);
  double shortest = std::numeric_limits<double>::max();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, norm(p[i] - p[j]));
  radius_edge = norm(x) / shortest;
}

void check_returned_points(const TetgenMesh& mesh, const std::vector<Vec3>& local_points) {
  if (mesh.points.size() / 3 < local_points.size())
    throw InputError("tetgen failed: it returned fewer points than it was given");
  for (std::size_t i = 0; i < local_points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (mesh.points[3 * i + k] != local_points[i][k])
        throw InputError("tetgen failed: input point " + std::to_string(i) + " came back moved or reordered");
}

// TetGen-local point index -> output index.
std::vector<std::int64_t> output_index(const FillPlc& plc, std::int64_t n_out, std::int64_t n_env,
                                       std::int64_t n_far) {
  std::vector<std::int64_t> to_out(static_cast<std::size_t>(n_out));
  const std::size_t n_local_env = plc.envelope.used.size();
  for (std::size_t i = 0; i < n_local_env; ++i) to_out[i] = plc.envelope.used[i];
  for (std::size_t i = 0; i < plc.farfield.used.size(); ++i) to_out[n_local_env + i] = n_env + plc.farfield.used[i];
  const std::int64_t n_local = static_cast<std::int64_t>(plc.points.size());
  for (std::int64_t i = 0; i < n_out - n_local; ++i) to_out[n_local + i] = n_env + n_far + i;
  return to_out;
}

// TetGen's tets all have one (exactly computed) orientation; it is read from the tet
// with the largest |volume|, where double rounding cannot flip the sign, and turned
// positive for all.
void orient_positive(const std::vector<Vec3>& points, std::vector<PointId>& conn) {
  const std::int64_t n_tets = static_cast<std::int64_t>(conn.size() / 4);
  auto tet_det = [&](std::int64_t t) {
    const PointId* c = &conn[4 * t];
    return det3(points[c[0]], points[c[1]], points[c[2]], points[c[3]]);
  };
  std::int64_t largest = 0;
  for (std::int64_t t = 1; t < n_tets; ++t)
    if (std::abs(tet_det(t)) > std::abs(tet_det(largest))) largest = t;
  if (tet_det(largest) < 0.0)
    for (std::int64_t t = 0; t < n_tets; ++t) std::swap(conn[4 * t + 1], conn[4 * t + 2]);
}

// Faces of the tets used by exactly one tet, sorted by key; throws on a face of three.
std::vector<FaceRef> single_faces(const std::vector<PointId>& conn) {
  const std::int64_t n_tets = static_cast<std::int64_t>(conn.size() / 4);
  std::vector<FaceRef> faces;
  faces.reserve(4 * static_cast<std::size_t>(n_tets));
  static const int kOpp[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (std::int64_t t = 0; t < n_tets; ++t)
    for (const auto& f : kOpp) faces.push_back({sorted_triangle(conn[4 * t + f[0]], conn[4 * t + f[1]], conn[4 * t + f[2]]), t});
  std::sort(faces.begin(), faces.end(), [](const FaceRef& a, const FaceRef& b) { return a.key < b.key; });
  std::vector<FaceRef> single;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i > 2)
      throw InputError("tetgen failed: the tet mesh is not conforming (a face shared by " + std::to_string(j - i) +
                       " tets)");
    if (j - i == 1) single.push_back(faces[i]);
    i = j;
  }
  return single;
}

}  // namespace

void assemble_fill_result(const TriSurface& envelope, const OuterBoundary& outer, const FillPlc& plc,
                          const TetgenMesh& mesh, FillResult* result) {
  const TriSurface& far = outer.surface;
  check_returned_points(mesh, plc.points);
  const std::int64_t n_out = static_cast<std::int64_t>(mesh.points.size() / 3);
  const std::int64_t n_env = static_cast<std::int64_t>(envelope.points.size());
  const std::int64_t n_far = static_cast<std::int64_t>(far.points.size());
  const std::vector<std::int64_t> to_out = output_index(plc, n_out, n_env, n_far);

  VolumeMesh& vm = result->tets;
  vm.points = envelope.points;
  vm.points.insert(vm.points.end(), far.points.begin(), far.points.end());
  for (std::size_t j = 3 * plc.points.size(); j < mesh.points.size(); j += 3)
    vm.points.push_back({mesh.points[j], mesh.points[j + 1], mesh.points[j + 2]});

  const std::int64_t n_tets = static_cast<std::int64_t>(mesh.tets.size() / 4);
  if (n_tets == 0) throw InputError("tetgen failed: it returned no tetrahedra");
  require_indexable_points(vm.points.size(), "tet fill");
  std::vector<PointId> conn(mesh.tets.size());
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    if (mesh.tets[i] < 0 || mesh.tets[i] >= n_out)
      throw InputError("tetgen failed: a tetrahedron refers to a point it did not return");
    conn[i] = to_out[mesh.tets[i]];
  }
  orient_positive(vm.points, conn);
  vm.cell_types.assign(static_cast<std::size_t>(n_tets), CellType::kTet);
  vm.offsets.resize(static_cast<std::size_t>(n_tets) + 1);
  for (std::int64_t t = 0; t <= n_tets; ++t) vm.offsets[t] = 4 * t;
  vm.connectivity = std::move(conn);

  result->boundary.points = vm.points;
  for (const Triangle& t : envelope.triangles) {
    result->boundary.triangles.push_back(t);
    result->boundary_marker.push_back(kEnvelopeMarker);
  }
  const int offset = static_cast<int>(n_env);
  for (std::size_t f = 0; f < far.triangles.size(); ++f) {
    Triangle t = far.triangles[f];
    for (int& v : t) v = outer.is_envelope_point(v) ? outer.envelope_point(v) : v + offset;
    result->boundary.triangles.push_back(t);
    result->boundary_marker.push_back(outer.markers[f]);
  }
  result->stats.n_steiner_points = n_out - static_cast<std::int64_t>(plc.points.size());
  result->stats.n_tets = n_tets;
}

void check_conformity(const FillResult& result) {
  const std::vector<PointId>& conn = result.tets.connectivity;
  const std::vector<FaceRef> single = single_faces(conn);
  std::vector<std::pair<TriangleKey, std::size_t>> bnd;
  for (std::size_t b = 0; b < result.boundary.triangles.size(); ++b) {
    const Triangle& t = result.boundary.triangles[b];
    bnd.push_back({sorted_triangle(t[0], t[1], t[2]), b});
  }
  std::sort(bnd.begin(), bnd.end());
  std::size_t n_missing = 0;
  for (std::size_t i = 0, j = 0; i < bnd.size(); ++i) {
    while (j < single.size() && single[j].key < bnd[i].first) ++j;
    if (j == single.size() || single[j].key != bnd[i].first) {
      ++n_missing;
      continue;
    }
    // The tet on this boundary triangle must lie on the side its normal points to.
    const Triangle& t = result.boundary.triangles[bnd[i].second];
    const PointId* c = &conn[4 * single[j].tet];
    std::int64_t d = -1;
    for (int k = 0; k < 4; ++k)
      if (c[k] != t[0] && c[k] != t[1] && c[k] != t[2]) d = c[k];
    if (!even_permutation(c, {t[0], t[1], t[2], d}))
      throw InputError("tet fill: tets lie on the wrong side of boundary triangle " + std::to_string(bnd[i].second) +
                       "; the hole seeds selected the wrong region");
  }
  if (n_missing > 0 || single.size() != bnd.size())
    throw InputError("tetgen failed: the tets do not conform to the boundary (" + std::to_string(n_missing) +
                     " boundary triangles are not tet faces, " + std::to_string(single.size()) +
                     " faces lie on the mesh boundary for " + std::to_string(bnd.size()) +
                     " boundary triangles); TetGen split the boundary despite the Y switch");
}

void add_quality_stats(FillResult* result) {
  FillStats& st = result->stats;
  const VolumeMesh& vm = result->tets;
  const std::int64_t first_steiner = st.n_envelope_points + st.n_farfield_points;
  BLAYER_ASSERT(first_steiner + st.n_steiner_points == static_cast<std::int64_t>(vm.points.size()));
  st.min_dihedral_deg = 180.0;
  st.min_dihedral_deg_interior = 180.0;
  st.max_radius_edge = 0.0;
  st.min_tet_volume = std::numeric_limits<double>::max();
  for (std::size_t t = 0; t < vm.n_cells(); ++t) {
    const PointId* c = vm.cell_nodes(t);
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) p[k] = vm.points[c[k]];
    double dihedral, radius_edge;
    tet_quality(p, dihedral, radius_edge);
    st.min_dihedral_deg = std::min(st.min_dihedral_deg, dihedral * 180.0 / kPi);
    bool interior = true;
    for (int k = 0; k < 4; ++k) interior = interior && c[k] >= first_steiner;
    if (interior) st.min_dihedral_deg_interior = std::min(st.min_dihedral_deg_interior, dihedral * 180.0 / kPi);
    st.max_radius_edge = std::max(st.max_radius_edge, radius_edge);
    st.min_tet_volume = std::min(st.min_tet_volume, det3(p[0], p[1], p[2], p[3]) / 6.0);
  }
}

}  // namespace blayer::fill_detail
