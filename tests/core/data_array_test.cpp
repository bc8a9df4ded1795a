#include "blayer/core/data_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace blayer {
namespace {

TEST(DataArray, ValuesAreStoredAsTheTypeTheyAreWrittenAs) {
  ArrayValues f64(ValueType::kFloat64), f32(ValueType::kFloat32), i32(ValueType::kInt32);
  for (ArrayValues* a : {&f64, &f32, &i32}) {
    a->push_back(0.1);
    a->push_back(-2.75);
  }
  EXPECT_EQ(f64.as<double>(), (std::vector<double>{0.1, -2.75}));
  EXPECT_EQ(f32.as<float>(), (std::vector<float>{0.1f, -2.75f}));
  // Truncated towards zero, as writing an integer array as Int32 always did.
  EXPECT_EQ(i32.as<std::int32_t>(), (std::vector<std::int32_t>{0, -2}));
  EXPECT_EQ(f32[0], static_cast<double>(0.1f));
  EXPECT_EQ(i32[1], -2.0);
}

TEST(DataArray, ResizeAndSetKeepTheType) {
  ArrayValues a(ValueType::kInt32, 2);
  a.resize(4, -1.0);
  a.set(1, 7.0);
  EXPECT_EQ(a.type(), ValueType::kInt32);
  EXPECT_EQ(a.as<std::int32_t>(), (std::vector<std::int32_t>{0, 7, -1, -1}));
}

TEST(DataArray, ConvertedFromDoublesOrTakenOverFromTheirOwnType) {
  const ArrayValues from_doubles(ValueType::kFloat32, std::vector<double>{1.0 / 3.0, 2.0});
  const ArrayValues taken(std::vector<float>{1.0f / 3.0f, 2.0f});
  EXPECT_EQ(from_doubles, taken);
  const ArrayValues doubles(std::vector<double>{1.0 / 3.0, 2.0});
  EXPECT_EQ(doubles.type(), ValueType::kFloat64);
  // The same values in another type are another array.
  EXPECT_FALSE(doubles == from_doubles);
  EXPECT_FALSE(ArrayValues(std::vector<std::int32_t>{2}) == ArrayValues(std::vector<double>{2.0}));
}

TEST(DataArray, KindsFollowTheStoredType) {
  const DataArray layer{"layer", 1, ArrayValues(ValueType::kInt32, 3)};
  const DataArray volume{"volume", 1, ArrayValues(ValueType::kFloat32, 3)};
  const DataArray normal{"normal", 3, std::vector<double>(9)};
  EXPECT_TRUE(layer.integer());
  EXPECT_FALSE(layer.single_precision());
  EXPECT_TRUE(volume.single_precision());
  EXPECT_FALSE(volume.integer());
  EXPECT_FALSE(normal.integer() || normal.single_precision());
  EXPECT_EQ(normal.values.size(), 9u);
}

}  // namespace
}  // namespace blayer
