// libFuzzer harness: the whole pipeline on tiny closed surfaces. An icosahedron (or a
// box) has its vertices moved by the input, then is prepared, extruded with parameters
// from the input, and the result checked by the independent mesh check.
//
// Invariants: whatever prepare_surface accepts and the extruder does not refuse yields
// a mesh that passes check_volume_mesh (no inverted, twisted or flat cell, conforming
// faces) and, with the collision check on, an envelope that meets neither itself nor
// the wall.
#include <fuzzer/FuzzedDataProvider.h>

#include "analytic_surfaces.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/quality/mesh_check.h"
#include "fuzz_support.h"

namespace {

blayer::PolygonSoup moved_surface(FuzzedDataProvider& in) {
  const blayer::TriSurface base = in.ConsumeBool()
                                      ? blayer::test_surfaces::icosphere(0)
                                      : blayer::test_surfaces::box({0, 0, 0}, {1, 1, 1}, 1);
  blayer::PolygonSoup s;
  s.points = base.points;
  for (blayer::Vec3& p : s.points)
    for (double& c : p) c += in.ConsumeFloatingPointInRange(-0.4, 0.4) * (in.ConsumeBool() ? 1.0 : 0.0);
  for (const blayer::Triangle& t : base.triangles) s.faces.push_back({t[0], t[1], t[2]});
  return s;
}

blayer::ExtrusionParams params_from(FuzzedDataProvider& in) {
  blayer::ExtrusionParams e;
  e.growth.layers = in.ConsumeIntegralInRange(1, 6);
  e.growth.first_height = in.ConsumeFloatingPointInRange(1e-4, 0.2);
  e.growth.growth_ratio = in.ConsumeFloatingPointInRange(0.8, 2.0);
  const auto methods = blayer::normal_method_names();
  blayer::parse_normal_method(methods[in.ConsumeIntegralInRange<std::size_t>(0, methods.size() - 1)], &e.normal_method);
  e.normal_smoothing_iterations = in.ConsumeIntegralInRange(0, 3);
  e.height_smoothing_rings = in.ConsumeIntegralInRange(0, 3);
  e.proximity_safety = in.ConsumeFloatingPointInRange(0.05, 0.5);
  e.direction_repair_passes = in.ConsumeIntegralInRange(0, 2);
  return e;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  using blayer::fuzz::broken;
  FuzzedDataProvider in(data, size);
  const blayer::PolygonSoup soup = moved_surface(in);
  blayer::PrepareOptions opt;
  opt.side = in.ConsumeBool() ? blayer::Side::kInward : blayer::Side::kOutward;
  const blayer::ExtrusionParams params = params_from(in);
  blayer::PreparedSurface wall;
  try {
    wall = blayer::prepare_surface(soup, "fuzz.off", opt);
  } catch (const blayer::InputError&) {
    return 0;
  }
  blayer::ExtrusionResult result;
  try {
    result = blayer::extrude_layers(wall.surface, params);
  } catch (const blayer::InputError&) {
    return 0;
  }
  const blayer::MeshCheckReport check = blayer::check_volume_mesh(result.mesh);
  if (!check.ok())
    broken("extruded mesh fails the check: " + std::to_string(check.totals.inverted) + " inverted, " +
           std::to_string(check.totals.twisted) + " twisted, " + std::to_string(check.totals.flat) + " flat, " +
           std::to_string(check.totals.non_conforming) + " non-conforming");
  if (params.check_collisions && !blayer::find_envelope_intersections(wall.surface, result, 1).empty())
    broken("the envelope intersects itself or the wall");
  return 0;
}
