#include "blayer/quality/mesh_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "blayer/core/errors.h"
#include "test_cells.h"

namespace blayer {
namespace {

constexpr double kMetricTol = 1e-12;  // few-flop metrics from exact inputs

// A column of n_layers right prisms over the wall triangle (0,0,0), (1,0,0), (0,1,0),
// layer k between heights z[k] and z[k+1], with a `layer` cell array.
VolumeMesh prism_column(const std::vector<double>& z) {
  VolumeMesh m;
  for (double h : z) {
    m.points.push_back({0, 0, h});
    m.points.push_back({1, 0, h});
    m.points.push_back({0, 1, h});
  }
  DataArray layer{"layer", 1, ArrayValues(ValueType::kInt32)};
  for (std::size_t k = 0; k + 1 < z.size(); ++k) {
    const auto b = static_cast<std::int64_t>(3 * k), t = b + 3;
    const std::int64_t nodes[6] = {b, b + 2, b + 1, t, t + 2, t + 1};  // (a, c, b, a', c', b')
    m.add_cell(CellType::kWedge, nodes);
    layer.values.push_back(static_cast<double>(k));
  }
  m.cell_data.push_back(layer);
  return m;
}

TEST(MeshCheck, ValidPrismColumnPassesWithGrowthRatiosAndPerLayerSummaries) {
  const VolumeMesh m = prism_column({0.0, 0.1, 0.22, 0.364});
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.totals.by_type[check_type_index(CellType::kWedge)], 3u);
  EXPECT_EQ(r.totals.inverted, 0u);
  EXPECT_EQ(r.totals.flat, 0u);
  EXPECT_EQ(r.totals.non_conforming, 0u);
  EXPECT_EQ(r.boundary_faces, 2u + 3u * 3u);  // bottom, top, three sides per layer
  EXPECT_EQ(r.upper_neighbour, (std::vector<std::int64_t>{1, 2, -1}));
  const std::vector<double>& growth = r.metrics[5];
  EXPECT_NEAR(growth[0], 1.2, kMetricTol);
  EXPECT_NEAR(growth[1], 1.2, kMetricTol);
  EXPECT_TRUE(std::isnan(growth[2]));
  ASSERT_EQ(r.layers.size(), 3u);
  EXPECT_EQ(r.layers[1].layer, 1);
  EXPECT_EQ(r.layers[1].counts.cells, 1u);
  EXPECT_NEAR(r.min_scaled_jacobian(), std::sqrt(0.5) * 2.0 / std::sqrt(3.0), kMetricTol);
}

TEST(MeshCheck, PerLayerSummariesGroupCellsByLayerValueInAnyOrderAndSkipNonFiniteOnes) {
  VolumeMesh m = prism_column({0.0, 0.1, 0.25, 0.3, 0.7, 0.75});
  const std::vector<double> values{2, 0, 2, std::nan(""), 1};
  m.cell_data = {DataArray{"layer", 1, values}};
  const MeshCheckReport r = check_volume_mesh(m);
  ASSERT_EQ(r.layers.size(), 3u);
  // Oracle: each layer's cells picked by scanning, and their metrics' extremes.
  for (const LayerCheck& l : r.layers) {
    std::size_t cells = 0;
    double min_aspect = INFINITY, max_aspect = -INFINITY;
    for (std::size_t c = 0; c < values.size(); ++c)
      if (values[c] == static_cast<double>(l.layer)) {
        ++cells;
        min_aspect = std::min(min_aspect, r.metrics[2][c]);
        max_aspect = std::max(max_aspect, r.metrics[2][c]);
      }
    EXPECT_EQ(l.counts.cells, cells) << "layer " << l.layer;
    EXPECT_EQ(l.counts.by_type[check_type_index(CellType::kWedge)], cells) << "layer " << l.layer;
    EXPECT_EQ(l.counts.metrics[2].min, min_aspect) << "layer " << l.layer;
    EXPECT_EQ(l.counts.metrics[2].max, max_aspect) << "layer " << l.layer;
  }
  EXPECT_EQ(r.layers[0].layer, 0);
  EXPECT_EQ(r.layers[1].layer, 1);
  EXPECT_EQ(r.layers[2].layer, 2);
  EXPECT_EQ(r.layers[2].counts.cells, 2u);
  EXPECT_LT(r.layers[2].counts.metrics[2].min, r.layers[2].counts.metrics[2].max);  // two different cells
}

// kMinMax leaves out the percentiles and the layers, nothing else: the same per-cell
// results, counts and extremes as the full check, on a column with an inverted cell
// and a NaN metric (the top layer's growth ratio).
TEST(MeshCheck, MinMaxSummariesKeepTheCellsCountsAndExtremesOfTheFullCheck) {
  VolumeMesh m = prism_column({0.0, 0.1, 0.22, 0.364, 0.5});
  m.points[10][2] = 0.15;  // node b at the third level drops below the second level
  const MeshCheckReport full = check_volume_mesh(m);
  const MeshCheckReport minmax = check_volume_mesh(m, CheckSummaries::kMinMax);
  ASSERT_EQ(full.totals.inverted, 1u);
  EXPECT_EQ(minmax.totals.inverted, full.totals.inverted);
  EXPECT_EQ(minmax.totals.cells, full.totals.cells);
  EXPECT_EQ(minmax.totals.by_type, full.totals.by_type);
  EXPECT_EQ(minmax.validity, full.validity);
  EXPECT_EQ(minmax.flags, full.flags);
  EXPECT_EQ(minmax.upper_neighbour, full.upper_neighbour);
  EXPECT_EQ(minmax.boundary_faces, full.boundary_faces);
  ASSERT_EQ(minmax.totals.metrics.size(), full.totals.metrics.size());
  for (std::size_t k = 0; k < full.metrics.size(); ++k) {
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
      const double a = minmax.metrics[k][c], b = full.metrics[k][c];
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << "metric " << k << " cell " << c;
    }
    const MetricSummary& s = minmax.totals.metrics[k];
    EXPECT_EQ(s.name, full.totals.metrics[k].name);
    EXPECT_EQ(s.count, full.totals.metrics[k].count) << s.name;
    EXPECT_EQ(s.min, full.totals.metrics[k].min) << s.name;
    EXPECT_EQ(s.max, full.totals.metrics[k].max) << s.name;
    EXPECT_TRUE(std::isnan(s.p50)) << s.name;
  }
  EXPECT_EQ(minmax.min_scaled_jacobian(), full.min_scaled_jacobian());
  EXPECT_LT(full.min_scaled_jacobian(), 0.0);
  EXPECT_EQ(full.layers.size(), 4u);
  EXPECT_TRUE(minmax.layers.empty());
}

TEST(MeshCheck, InvertedCellIsCountedAndExtractedWithItsArrays) {
  VolumeMesh m = prism_column({0.0, 0.1, 0.2, 0.3});
  m.points[7][2] = 0.05;  // node b at the second level drops below the first level
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.validity[0], Validity::kValid);
  EXPECT_EQ(r.validity[1], Validity::kInverted);
  EXPECT_EQ(r.totals.inverted, 1u);
  const VolumeMesh bad = extract_bad_cells(m, r);
  ASSERT_EQ(bad.n_cells(), 1u);
  EXPECT_EQ(bad.points.size(), 6u);
  const DataArray* original = bad.find_cell_array("original_cell_id");
  ASSERT_NE(original, nullptr);
  EXPECT_EQ(original->values, ArrayValues(std::vector<std::int32_t>{1}));
  ASSERT_NE(bad.find_cell_array("layer"), nullptr);
  EXPECT_EQ(bad.find_cell_array("layer")->values, ArrayValues(std::vector<std::int32_t>{1}));
  ASSERT_NE(bad.find_cell_array("validity"), nullptr);
  EXPECT_EQ(bad.find_cell_array("validity")->values, ArrayValues(std::vector<std::int32_t>{2}));
}

TEST(MeshCheck, FlatPrismIsCountedAsFlat) {
  VolumeMesh m = prism_column({0.0, 0.0});
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_EQ(r.totals.flat, 1u);
  EXPECT_EQ(r.totals.inverted, 0u);
  EXPECT_FALSE(r.ok());
}

// A hex whose top quad (4,5,6,7) is matched by the bottom caps of two prisms standing
// on its diagonal split: a non-conforming interface that is topologically invisible
// to matching faces by node set alone.
VolumeMesh hex_under_two_prisms() {
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},
              {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  const std::int64_t hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  m.add_cell(CellType::kHex, hex);
  // Wall triangles (4,5,6) and (4,6,7) have +z normals; VTK order (a, c, b, a', c', b').
  const std::int64_t w1[6] = {4, 6, 5, 8, 10, 9};
  const std::int64_t w2[6] = {4, 7, 6, 8, 11, 10};
  m.add_cell(CellType::kWedge, w1);
  m.add_cell(CellType::kWedge, w2);
  return m;
}

TEST(MeshCheck, QuadFaceMatchedByTwoTrianglesIsNonConforming) {
  const VolumeMesh m = hex_under_two_prisms();
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_EQ(r.totals.inverted, 0u);
  EXPECT_EQ(r.totals.non_conforming, 3u);
  EXPECT_EQ(r.non_conforming_faces, 3u);  // the quad and both triangles
  for (std::size_t c = 0; c < 3; ++c) EXPECT_TRUE(has_flag(r.flags[c], CellCheckFlag::kNonConforming));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(check_report_to_json(r)["non_conforming"], 3);
}

TEST(MeshCheck, TwoPrismsSharingAConformingFaceAreNotFlagged) {
  // Control for the previous test: the same two prisms on their own share the face
  // (4,6,8,10)-(4,6,10,8) properly.
  VolumeMesh m = hex_under_two_prisms();
  VolumeMesh prisms;
  prisms.points = m.points;
  const std::int64_t w1[6] = {4, 6, 5, 8, 10, 9};
  const std::int64_t w2[6] = {4, 7, 6, 8, 11, 10};
  prisms.add_cell(CellType::kWedge, w1);
  prisms.add_cell(CellType::kWedge, w2);
  const MeshCheckReport r = check_volume_mesh(prisms);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.boundary_faces, 8u);  // 2 x (2 caps + 3 quads) - 2 sides of the shared quad
}

TEST(MeshCheck, FaceSharedByThreeCellsIsDetected) {
  // Three tets on the common triangle (0,1,2): two above it and one below.
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 1}, {0.3, 0.3, -1}, {0.25, 0.2, 2}};
  const std::int64_t up[4] = {0, 1, 2, 3};
  const std::int64_t down[4] = {0, 2, 1, 4};
  const std::int64_t up2[4] = {0, 1, 2, 5};
  m.add_cell(CellType::kTet, up);
  m.add_cell(CellType::kTet, down);
  m.add_cell(CellType::kTet, up2);
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_EQ(r.totals.inverted, 0u);
  EXPECT_EQ(r.overshared_faces, 1u);
  for (std::size_t c = 0; c < 3; ++c) EXPECT_TRUE(has_flag(r.flags[c], CellCheckFlag::kOversharedFace));
  EXPECT_FALSE(r.ok());
}

TEST(MeshCheck, TwoCellsOnTheSameSideOfTheirFaceAreMisoriented) {
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 1}, {0.25, 0.2, 2}};
  const std::int64_t a[4] = {0, 1, 2, 3};
  const std::int64_t b[4] = {0, 1, 2, 4};
  m.add_cell(CellType::kTet, a);
  m.add_cell(CellType::kTet, b);
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_EQ(r.totals.inverted, 0u);
  EXPECT_EQ(r.misoriented_faces, 1u);
  EXPECT_FALSE(r.ok());
}

TEST(MeshCheck, CrossedQuadWithTheSameNodesIsNonConforming) {
  // Two hexes stacked, the upper one's bottom face listing the shared nodes in a
  // different cyclic order (a bow-tie), so the faces have the same node set only.
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
              {1, 1, 1}, {0, 1, 1}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  const std::int64_t lower[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::int64_t upper[8] = {4, 6, 5, 7, 8, 9, 10, 11};
  m.add_cell(CellType::kHex, lower);
  m.add_cell(CellType::kHex, upper);
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_TRUE(has_flag(r.flags[0], CellCheckFlag::kNonConforming));
  EXPECT_TRUE(has_flag(r.flags[1], CellCheckFlag::kNonConforming));
}

// Face matching by brute force, from the rules of mesh_check.h: faces grouped by node
// set; a group whose faces are not all one cyclic sequence (up to rotation and
// reversal) is non-conforming, one of more than two faces overshared, two faces read
// in the same direction misoriented, two read in opposite directions conforming (a
// top cap against a bottom cap makes an upper neighbour); a lone quad with triangles
// of other cells on three of its nodes is non-conforming with each of them, and any
// other lone face is boundary. Only for faces whose nodes are distinct.
struct FaceOracle {
  std::size_t boundary = 0, non_conforming = 0, overshared = 0, misoriented = 0;
  std::vector<std::uint8_t> flags;
  std::vector<std::int64_t> upper;
};

// Outward right-hand windings of the VTK cells' faces; for a wedge and a hex, face 0 is
// the bottom cap and face 1 the top cap.
std::vector<std::vector<int>> outward_faces(CellType t) {
  switch (t) {
    case CellType::kTet: return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    case CellType::kPyramid: return {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    case CellType::kWedge: return {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
    case CellType::kHex:
      return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  }
  return {};
}

// Whether b is a rotation of a.
bool rotation_of(const std::vector<std::int64_t>& a, const std::vector<std::int64_t>& b) {
  for (std::size_t r = 0; r < a.size(); ++r) {
    bool same = true;
    for (std::size_t i = 0; i < a.size(); ++i) same = same && b[i] == a[(i + r) % a.size()];
    if (same) return true;
  }
  return false;
}

FaceOracle brute_force_faces(const VolumeMesh& m) {
  struct Face {
    std::int64_t cell;
    int face;
    std::vector<std::int64_t> nodes, set;
  };
  std::vector<Face> faces;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const std::vector<std::vector<int>> fs = outward_faces(m.cell_types[c]);
    for (std::size_t f = 0; f < fs.size(); ++f) {
      Face x{static_cast<std::int64_t>(c), static_cast<int>(f), {}, {}};
      for (int v : fs[f]) x.nodes.push_back(m.cell_nodes(c)[v]);
      x.set = x.nodes;
      std::sort(x.set.begin(), x.set.end());
      faces.push_back(x);
    }
  }
  FaceOracle o;
  o.flags.assign(m.n_cells(), 0);
  o.upper.assign(m.n_cells(), -1);
  auto mark = [&](std::int64_t c, CellCheckFlag f) { o.flags[c] |= static_cast<std::uint8_t>(f); };
  std::vector<char> grouped(faces.size(), 0);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (grouped[i]) continue;
    std::vector<std::size_t> group;
    for (std::size_t j = i; j < faces.size(); ++j)
      if (faces[j].set == faces[i].set) {
        group.push_back(j);
        grouped[j] = 1;
      }
    const Face& a = faces[i];
    std::vector<std::int64_t> reversed_a(a.nodes.rbegin(), a.nodes.rend());
    bool one_sequence = true;
    for (std::size_t j : group) one_sequence = one_sequence && (rotation_of(a.nodes, faces[j].nodes) || rotation_of(reversed_a, faces[j].nodes));
    if (!one_sequence) {
      ++o.non_conforming;
      for (std::size_t j : group) mark(faces[j].cell, CellCheckFlag::kNonConforming);
    } else if (group.size() > 2) {
      ++o.overshared;
      for (std::size_t j : group) mark(faces[j].cell, CellCheckFlag::kOversharedFace);
    } else if (group.size() == 2) {
      const Face& b = faces[group[1]];
      if (rotation_of(a.nodes, b.nodes)) {
        ++o.misoriented;
        mark(a.cell, CellCheckFlag::kMisorientedFace);
        mark(b.cell, CellCheckFlag::kMisorientedFace);
      } else {
        auto capped = [&](CellType t) { return t == CellType::kWedge || t == CellType::kHex; };
        for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}})
          if (capped(m.cell_types[x->cell]) && capped(m.cell_types[y->cell]) && x->face == 1 && y->face == 0)
            o.upper[x->cell] = y->cell;
      }
    } else if (a.nodes.size() == 4) {
      std::size_t found = 0;
      for (const Face& t : faces)
        if (t.cell != a.cell && t.nodes.size() == 3 &&
            std::includes(a.set.begin(), a.set.end(), t.set.begin(), t.set.end())) {
          ++found;
          mark(t.cell, CellCheckFlag::kNonConforming);
        }
      if (found > 0) {
        mark(a.cell, CellCheckFlag::kNonConforming);
        o.non_conforming += 1 + found;
      } else {
        ++o.boundary;
      }
    } else {
      ++o.boundary;
    }
  }
  return o;
}

TEST(MeshCheck, FaceMatchingAgreesWithABruteForceMatcherOnRandomCellSoups) {
  // Cells on a few shared nodes, so that faces meet in every way: repeated, reversed,
  // crossed, quads over triangles; and stacked wedges and hexes for the upper
  // neighbours. Geometry does not enter the matching.
  std::mt19937 rng(20261206);
  const CellType types[4] = {CellType::kTet, CellType::kPyramid, CellType::kWedge, CellType::kHex};
  std::size_t totals[4] = {0, 0, 0, 0}, uppers = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int n_points = 6 + static_cast<int>(rng() % 6);
    VolumeMesh m;
    for (int i = 0; i < n_points; ++i) m.points.push_back({double(i), double(i * i % 7), double(i % 3)});
    std::vector<std::int64_t> pool(n_points);
    for (int i = 0; i < n_points; ++i) pool[i] = i;
    const int n_cells = 1 + static_cast<int>(rng() % 10);
    for (int c = 0; c < n_cells; ++c) {
      const CellType t = types[rng() % 4];
      std::shuffle(pool.begin(), pool.end(), rng);
      const int k = corner_count(t);
      if (k > n_points) continue;
      m.add_cell(t, pool.data());
      if ((t == CellType::kWedge || t == CellType::kHex) && rng() % 2 == 0) {
        // The next cell up: its bottom cap is this cell's top cap read the other way;
        // its top on this cell's bottom nodes, in any order.
        std::vector<std::int64_t> up(pool.begin() + k / 2, pool.begin() + k);
        std::vector<std::int64_t> top(pool.begin(), pool.begin() + k / 2);
        std::shuffle(top.begin(), top.end(), rng);
        up.insert(up.end(), top.begin(), top.end());
        m.add_cell(t, up.data());
      }
    }
    const MeshCheckReport r = check_volume_mesh(m, CheckSummaries::kMinMax);
    const FaceOracle o = brute_force_faces(m);
    ASSERT_EQ(r.boundary_faces, o.boundary) << trial;
    ASSERT_EQ(r.non_conforming_faces, o.non_conforming) << trial;
    ASSERT_EQ(r.overshared_faces, o.overshared) << trial;
    ASSERT_EQ(r.misoriented_faces, o.misoriented) << trial;
    const std::uint8_t face_bits = static_cast<std::uint8_t>(CellCheckFlag::kNonConforming) |
                                   static_cast<std::uint8_t>(CellCheckFlag::kOversharedFace) |
                                   static_cast<std::uint8_t>(CellCheckFlag::kMisorientedFace);
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
      ASSERT_EQ(r.flags[c] & face_bits, o.flags[c]) << trial << " cell " << c;
      ASSERT_EQ(r.upper_neighbour[c], o.upper[c]) << trial << " cell " << c;
      uppers += o.upper[c] >= 0;
    }
    totals[0] += o.boundary;
    totals[1] += o.non_conforming;
    totals[2] += o.overshared;
    totals[3] += o.misoriented;
  }
  // Every kind of face occurred (else the comparison proved little).
  for (std::size_t t : totals) EXPECT_GT(t, 50u);
  EXPECT_GT(uppers, 50u);
}

TEST(MeshCheck, StructuralErrorsThrowInputError) {
  VolumeMesh m = prism_column({0.0, 1.0});
  m.connectivity[3] = 99;
  EXPECT_THROW(check_volume_mesh(m), InputError);
  VolumeMesh short_offsets = prism_column({0.0, 1.0});
  short_offsets.offsets.pop_back();
  EXPECT_THROW(check_volume_mesh(short_offsets), InputError);
}

TEST(MeshCheck, AStructuralErrorNamesTheFirstIllFormedCell) {
  // The cells are scanned in parallel: of several ill-formed cells far apart, the
  // message names the first, as a scan in order does.
  std::vector<double> z(50001);
  for (std::size_t k = 0; k < z.size(); ++k) z[k] = 0.1 * static_cast<double>(k);
  VolumeMesh m = prism_column(z);
  auto message = [&] {
    try {
      check_volume_mesh(m);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  m.connectivity[6 * 41000 + 2] = -1;
  m.connectivity[6 * 23456 + 4] = static_cast<PointId>(m.points.size());
  m.connectivity[6 * 30000] = 1 << 30;
  EXPECT_EQ(message(), "check_volume_mesh: cell 23456 uses node " + std::to_string(m.points.size()) +
                           ", outside [0, " + std::to_string(m.points.size()) + ")");
  m.connectivity[6 * 23456 + 4] = 0;
  EXPECT_EQ(message(), "check_volume_mesh: cell 30000 uses node 1073741824, outside [0, " +
                           std::to_string(m.points.size()) + ")");
}

TEST(MeshCheck, NonFinitePointMakesItsCellInvalid) {
  VolumeMesh m = prism_column({0.0, 1.0});
  m.points[4][0] = std::nan("");
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_EQ(r.validity[0], Validity::kInverted);
  EXPECT_TRUE(has_flag(r.flags[0], CellCheckFlag::kNonFinite));
}

TEST(MeshCheck, JsonHasTheDocumentedKeys) {
  const MeshCheckReport r = check_volume_mesh(prism_column({0.0, 0.1, 0.2}));
  const nlohmann::json j = check_report_to_json(r);
  EXPECT_EQ(j["cells"]["wedge"], 2);
  EXPECT_EQ(j["cells"]["tet"], 0);
  EXPECT_EQ(j["cells"]["pyramid"], 0);
  EXPECT_EQ(j["cells"]["hex"], 0);
  EXPECT_EQ(j["inverted"], 0);
  EXPECT_EQ(j["flat"], 0);
  EXPECT_EQ(j["non_conforming"], 0);
  EXPECT_EQ(j["ok"], true);
  EXPECT_NEAR(j["min_scaled_jacobian"].get<double>(), r.min_scaled_jacobian(), 0.0);
  EXPECT_EQ(j["metrics"]["orthogonality_deg"]["count"], 2);
  ASSERT_EQ(j["layers"].size(), 2u);
  EXPECT_EQ(j["layers"][1]["layer"], 1);
  EXPECT_TRUE(j["metrics"]["growth_ratio"]["max"].is_number());
}

TEST(MeshCheck, TextReportNamesCountsAndLayers) {
  VolumeMesh m = prism_column({0.0, 0.1, 0.2});
  m.points[5][2] = -0.5;
  const std::string text = format_check_report(check_volume_mesh(m));
  EXPECT_NE(text.find("FAILED"), std::string::npos);
  EXPECT_NE(text.find("inverted: 1"), std::string::npos);
  EXPECT_NE(text.find("wedge 2"), std::string::npos);
  EXPECT_NE(text.find("layer 1:"), std::string::npos);
  EXPECT_NE(text.find("min_corner_jacobian"), std::string::npos);
}

TEST(MeshCheck, QualityArraysAreAddedOncePerName) {
  VolumeMesh m = prism_column({0.0, 0.1, 0.2});
  add_quality_arrays(m);
  add_quality_arrays(m);
  for (const char* name : {"min_corner_jacobian", "skewness", "aspect_ratio", "orthogonality_deg", "twist",
                           "growth_ratio", "volume", "validity", "check_flags"}) {
    int copies = 0;
    for (const DataArray& a : m.cell_data) copies += a.name == name;
    EXPECT_EQ(copies, 1) << name;
    ASSERT_NE(m.find_cell_array(name), nullptr);
    EXPECT_EQ(m.find_cell_array(name)->values.size(), 2u) << name;
  }
  EXPECT_TRUE(m.find_cell_array("validity")->integer());
  // Stored as Float32: the metric rounded to float (within gtest's 4 float ulps).
  EXPECT_FLOAT_EQ(m.find_cell_array("aspect_ratio")->values[0], (2.0 + std::sqrt(2.0)) / 3.0 / 0.1);
}

TEST(MeshCheck, MovedQualityArraysEqualCopiedOnesAndTheReportKeepsItsTotals) {
  VolumeMesh copied = prism_column({0.0, 0.1, 0.25});
  copied.points[5][2] = -0.5;  // one inverted cell: validity and flags are not all zero
  VolumeMesh moved = copied;
  const MeshCheckReport kept = check_volume_mesh(copied);
  MeshCheckReport taken = check_volume_mesh(moved);
  add_quality_arrays(copied, kept);
  move_quality_arrays(moved, &taken);
  ASSERT_EQ(copied.cell_data.size(), moved.cell_data.size());
  for (std::size_t i = 0; i < copied.cell_data.size(); ++i) {
    const DataArray& a = copied.cell_data[i];
    const DataArray& b = moved.cell_data[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.integer(), b.integer()) << a.name;
    EXPECT_EQ(a.single_precision(), b.single_precision()) << a.name;
    ASSERT_EQ(a.values.size(), b.values.size()) << a.name;
    for (std::size_t c = 0; c < a.values.size(); ++c)
      EXPECT_TRUE(a.values[c] == b.values[c] || (std::isnan(a.values[c]) && std::isnan(b.values[c])))
          << a.name << " cell " << c;
  }
  for (const std::vector<double>& m : taken.metrics) EXPECT_TRUE(m.empty());
  EXPECT_EQ(taken.totals.inverted, 1u);
  EXPECT_EQ(taken.totals.inverted, kept.totals.inverted);
  EXPECT_EQ(taken.validity, kept.validity);
  EXPECT_FALSE(taken.ok());
}

}  // namespace
}  // namespace blayer
