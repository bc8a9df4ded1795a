// Independent checks of a tet fill, written against the contract in tet_fill.h.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <map>
#include <set>

#include "blayer/fill/tet_fill.h"
#include "blayer/quality/orient3d.h"

namespace blayer::fill_test {

// Six times the signed volume, in long double: only summed for the domain volume.
inline long double det_ld(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  long double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = static_cast<long double>(b[k]) - a[k];
    v[k] = static_cast<long double>(c[k]) - a[k];
    w[k] = static_cast<long double>(d[k]) - a[k];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

inline std::array<std::int64_t, 3> face_key(std::int64_t a, std::int64_t b, std::int64_t c) {
  std::array<std::int64_t, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

struct MeshFigures {
  long double volume = 0;  // sum of tet volumes
  std::size_t n_nonpositive = 0;
  std::size_t n_interior_faces = 0;
};

// Checks: all cells are tets with valid indices and positive volume (exact orient3d);
// every face is shared by one or two tets; faces with one tet are exactly the boundary
// triangles; each boundary triangle (a,b,c) is a tet face whose fourth vertex lies on
// the side its normal points to (node for node, same indices).
inline MeshFigures check_fill(const FillResult& r) {
  MeshFigures fig;
  const VolumeMesh& m = r.tets;
  const std::int64_t np = static_cast<std::int64_t>(m.points.size());
  std::map<std::array<std::int64_t, 3>, std::vector<std::pair<std::size_t, std::int64_t>>> faces;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    EXPECT_EQ(m.cell_types[c], CellType::kTet);
    EXPECT_EQ(m.offsets[c + 1] - m.offsets[c], 4);
    const PointId* n = m.cell_nodes(c);
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(n[k], 0);
      EXPECT_LT(n[k], np);
    }
    const Vec3 &a = m.points[n[0]], &b = m.points[n[1]], &cc = m.points[n[2]], &d = m.points[n[3]];
    if (orient3d_sign(a, b, cc, d) <= 0) ++fig.n_nonpositive;
    const long double det = det_ld(a, b, cc, d);
    fig.volume += det / 6.0L;
    static const int kFaces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
    for (const auto& f : kFaces) faces[face_key(n[f[0]], n[f[1]], n[f[2]])].push_back({c, n[f[3]]});
  }
  std::set<std::array<std::int64_t, 3>> boundary;
  for (const Triangle& t : r.boundary.triangles) boundary.insert(face_key(t[0], t[1], t[2]));
  EXPECT_EQ(boundary.size(), r.boundary.triangles.size()) << "duplicate boundary triangles";
  std::size_t n_single = 0;
  for (const auto& [key, uses] : faces) {
    EXPECT_LE(uses.size(), 2u) << "face shared by more than two tets";
    if (uses.size() == 1) {
      ++n_single;
      EXPECT_TRUE(boundary.count(key)) << "a boundary face of the tets is not an input triangle";
    } else {
      ++fig.n_interior_faces;
      EXPECT_FALSE(boundary.count(key)) << "a boundary triangle has tets on both sides";
    }
  }
  EXPECT_EQ(n_single, r.boundary.triangles.size());
  for (const Triangle& t : r.boundary.triangles) {
    auto it = faces.find(face_key(t[0], t[1], t[2]));
    if (it == faces.end()) {
      ADD_FAILURE() << "boundary triangle is not a tet face";
      continue;
    }
    const std::int64_t d = it->second.front().second;
    EXPECT_GT(orient3d_sign(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[d]), 0)
        << "tet lies behind a boundary triangle's normal";
  }
  EXPECT_EQ(fig.n_nonpositive, 0u);
  return fig;
}

}  // namespace blayer::fill_test
