// libFuzzer harness: prepare_surface on polygon soups built from the input. Coordinates
// come mostly from a small lattice, so that coincident, collinear and coplanar points,
// touching and crossing triangles, nested and overlapping shells are common; faces
// have 1 to 6 vertices with indices that may be out of range.
//
// On success the result must hold what prepare_surface promises: valid indices, every
// edge used twice with opposite windings (closed surfaces), no intersecting triangles.
#include <fuzzer/FuzzedDataProvider.h>

#include <map>
#include <utility>

#include "blayer/core/edge_topology.h"
#include "blayer/io/surface_intersections.h"
#include "fuzz_support.h"

namespace {

blayer::PolygonSoup soup_from(FuzzedDataProvider& in) {
  blayer::PolygonSoup s;
  const int n_points = in.ConsumeIntegralInRange(0, 40);
  for (int i = 0; i < n_points; ++i) {
    blayer::Vec3 p;
    for (double& c : p)
      c = in.ConsumeBool() ? 0.5 * in.ConsumeIntegralInRange(-4, 4) : in.ConsumeFloatingPoint<double>();
    s.points.push_back(p);
  }
  const int n_faces = in.ConsumeIntegralInRange(0, 80);
  for (int f = 0; f < n_faces && in.remaining_bytes() > 0; ++f) {
    std::vector<int> face(in.ConsumeIntegralInRange(1, 6));
    for (int& v : face) v = in.ConsumeIntegralInRange(-1, n_points);
    s.faces.push_back(std::move(face));
  }
  return s;
}

void check_result(const blayer::PreparedSurface& p) {
  using blayer::fuzz::broken;
  const blayer::TriSurface& s = p.surface;
  for (const blayer::Triangle& t : s.triangles)
    for (int v : t)
      if (v < 0 || v >= static_cast<int>(s.points.size())) broken("triangle index out of range");
  const blayer::EdgeTopology edges = blayer::build_edge_topology(s);
  if (edges.n_non_manifold != 0 || edges.n_inconsistent != 0) broken("accepted a non-manifold or inconsistent surface");
  if (p.closed && edges.n_boundary != 0) broken("closed surface with boundary edges");
  if (!blayer::find_surface_intersections(s, 1).empty()) broken("accepted an intersecting surface");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  blayer::PrepareOptions opt;
  opt.allow_open = in.ConsumeBool();
  opt.side = in.ConsumeBool() ? blayer::Side::kInward : blayer::Side::kOutward;
  const blayer::PolygonSoup soup = soup_from(in);
  try {
    check_result(blayer::prepare_surface(soup, "fuzz.off", opt));
  } catch (const blayer::InputError&) {
  }
  return 0;
}
