// Nested closed components: which side of each is fluid follows from how many others
// enclose it (shell_nesting.h), so a cavity's layers grow into the cavity and a body in
// a duct gets its layers on the duct's side, whatever the file's winding.
#include "blayer/io/shell_nesting.h"

#include <gtest/gtest.h>

#include "blayer/core/edge_topology.h"
#include "blayer/io/prepare_surface.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

using testing::append;
using testing::box;

// Signed volume of each component of a prepared surface, in component order.
std::vector<double> component_volumes(const TriSurface& s) {
  const EdgeTopology edges = build_edge_topology(s);
  return component_signed_volumes(s, edge_connected_components(s, edges));
}

// Three boxes: 0 = [0,5]^3, 1 = [1,4]^3 inside it, 2 = [2,3]^3 inside both, all wound
// outward in the file; and 3 = [6,7]^3 beside them.
PolygonSoup nested_boxes(bool all_inward_in_file = false) {
  PolygonSoup s = box({0, 0, 0}, {5, 5, 5}, all_inward_in_file);
  append(&s, box({1, 1, 1}, {4, 4, 4}, all_inward_in_file));
  append(&s, box({2, 2, 2}, {3, 3, 3}, all_inward_in_file));
  append(&s, box({6, 0, 0}, {7, 1, 1}, all_inward_in_file));
  return s;
}

TEST(ShellNesting, DepthCountsTheEnclosingShellsAndNamesTheInnermost) {
  const PolygonSoup soup = nested_boxes();
  TriSurface s{soup.points, {}};
  for (const auto& f : soup.faces) s.triangles.push_back({f[0], f[1], f[2]});
  const SurfaceComponents comps = edge_connected_components(s, build_edge_topology(s));
  ASSERT_EQ(comps.count, 4);
  const ShellNesting n = nest_closed_components(s, comps, std::vector<char>(4, 1));
  EXPECT_EQ(n.depth, (std::vector<int>{0, 1, 2, 0}));
  EXPECT_EQ(n.enclosing, (std::vector<int>{-1, 0, 1, -1}));
  EXPECT_TRUE(n.undecided.empty());
}

TEST(ShellNesting, OpenComponentsEncloseNothing) {
  PolygonSoup soup = box({0, 0, 0}, {5, 5, 5});
  soup.faces.pop_back();  // the outer box is open now
  append(&soup, box({1, 1, 1}, {2, 2, 2}));
  TriSurface s{soup.points, {}};
  for (const auto& f : soup.faces) s.triangles.push_back({f[0], f[1], f[2]});
  const SurfaceComponents comps = edge_connected_components(s, build_edge_topology(s));
  const ShellNesting n = nest_closed_components(s, comps, {0, 1});
  EXPECT_EQ(n.depth, (std::vector<int>{0, 0}));
}

TEST(ShellNesting, ExternalFlowOrientsACavityIntoItselfAndABodyInTheCavityOutward) {
  for (bool file_inward : {false, true}) {
    const PreparedSurface p = prepare_surface(nested_boxes(file_inward), "nested.off", {});
    const std::vector<double> v = component_volumes(p.surface);
    ASSERT_EQ(v.size(), 4u);
    EXPECT_NEAR(v[0], 125.0, 1e-9) << "outer skin: fluid outside";
    EXPECT_NEAR(v[1], -27.0, 1e-9) << "cavity wall: fluid inside the cavity";
    EXPECT_NEAR(v[2], 1.0, 1e-9) << "body inside the cavity: fluid outside";
    EXPECT_NEAR(v[3], 1.0, 1e-9) << "separate body: fluid outside";
    EXPECT_EQ(p.n_flipped_components, file_inward ? 3 : 1);
  }
}

TEST(ShellNesting, InternalFlowOrientsADuctInwardAndABodyInsideItOutward) {
  PrepareOptions inward;
  inward.side = Side::kInward;
  PolygonSoup s = box({0, 0, 0}, {5, 5, 5});
  append(&s, box({2, 2, 2}, {3, 3, 3}));
  const PreparedSurface p = prepare_surface(s, "duct.off", inward);
  const std::vector<double> v = component_volumes(p.surface);
  EXPECT_NEAR(v[0], -125.0, 1e-9) << "duct wall: fluid inside";
  EXPECT_NEAR(v[1], 1.0, 1e-9) << "body in the duct: fluid outside";
}

TEST(ShellNesting, NestedComponentsGetANoteSayingWhichSideIsFluid) {
  PolygonSoup s = box({0, 0, 0}, {3, 3, 3});
  append(&s, box({1, 1, 1}, {2, 2, 2}));
  const PreparedSurface p = prepare_surface(s, "hollow.off", {});
  bool noted = false;
  for (const std::string& n : p.notes)
    noted = noted || n.find("closed component 1 lies inside component 0 (nesting depth 1): it bounds a cavity, "
                            "fluid inside") != std::string::npos;
  EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace blayer
