#include "blayer/core/volume_mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace blayer {
namespace {

TEST(VolumeMesh, CellsFromIdsOfAnyWidthKeepTheirCornersInOrder) {
  VolumeMesh m;
  const std::int64_t wide[4] = {3, 0, 2, 1};
  const int narrow[6] = {5, 4, 3, 2, 1, 0};
  m.add_cell(CellType::kTet, wide);
  m.add_cell(CellType::kWedge, narrow);
  ASSERT_EQ(m.n_cells(), 2u);
  ASSERT_EQ(m.offsets.size(), 3u);
  EXPECT_EQ(m.offsets[1], 4);
  EXPECT_EQ(m.offsets[2], 10);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(m.cell_nodes(0)[i], wide[i]);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(m.cell_nodes(1)[i], narrow[i]);
}

TEST(VolumeMesh, PointCountsPastTheIdRangeAreRefusedByName) {
  EXPECT_NO_THROW(require_indexable_points(static_cast<std::size_t>(kMaxMeshPoints), "layers"));
  try {
    require_indexable_points(static_cast<std::size_t>(kMaxMeshPoints) + 1, "layer 7");
    FAIL() << "2^31 points were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "layer 7: 2147483648 points, more than a mesh can index (2147483647)");
  }
}

}  // namespace
}  // namespace blayer
