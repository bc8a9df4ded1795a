#include <gtest/gtest.h>

#include "blayer/core/vertex_fans.h"
#include "blayer/normals/point_normals.h"

namespace blayer {
namespace {

TEST(PointNormals, FlatSquareCentreGetsPlaneNormal) {
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  s.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
  const PointNormals pn = compute_point_normals(s, build_vertex_fans(s), NormalMethod::kAngle);
  EXPECT_DOUBLE_EQ(pn.normal[0][2], 1.0);
  EXPECT_EQ(pn.status[0], NormalStatus::kOk);
  EXPECT_EQ(pn.status[1], NormalStatus::kBoundary);
}

}  // namespace
}  // namespace blayer
