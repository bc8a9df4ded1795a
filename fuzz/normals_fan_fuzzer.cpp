// libFuzzer harness: point normals of a random closed fan, one vertex at the origin
// with a ring of 3 to 24 neighbours (any positions: folded, flat, slivered, repeated),
// by every method.
//
// Invariants at the centre vertex: the normal is finite and of unit length, or zero
// with the degenerate-fan status; visibility and normality are finite unless the fan is
// degenerate; a status that claims a visible direction (ok, tie, visibility-
// constrained) from an exact method comes with V > 0.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>

#include "blayer/core/vertex_fans.h"
#include "blayer/normals/point_normals.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  using blayer::fuzz::broken;
  FuzzedDataProvider in(data, size);
  const int k = in.ConsumeIntegralInRange(3, 24);
  blayer::TriSurface s;
  s.points.push_back({0, 0, 0});
  for (int i = 0; i < k; ++i) {
    blayer::Vec3 p;
    for (double& c : p)
      c = in.ConsumeBool() ? 0.25 * in.ConsumeIntegralInRange(-8, 8) : in.ConsumeFloatingPointInRange(-10.0, 10.0);
    s.points.push_back(p);
  }
  for (int i = 0; i < k; ++i) s.triangles.push_back({0, 1 + i, 1 + (i + 1) % k});
  const blayer::VertexFans fans = blayer::build_vertex_fans(s);
  const auto methods = blayer::normal_method_names();
  blayer::NormalMethod method;
  if (!blayer::parse_normal_method(methods[in.ConsumeIntegralInRange<std::size_t>(0, methods.size() - 1)], &method))
    broken("a listed normal method does not parse");
  const blayer::PointNormals pn = blayer::compute_point_normals(s, fans, method);
  const blayer::Vec3& n = pn.normal[0];
  const blayer::NormalStatus st = pn.status[0];
  if (!blayer::is_finite(n)) broken("non-finite normal");
  const double len = blayer::norm(n);
  if (!(std::abs(len - 1.0) < 1e-9 || (len == 0.0 && st == blayer::NormalStatus::kDegenerateFan)))
    broken("normal of length " + std::to_string(len));
  // A fan whose triangles all have zero area has no face normal to take a minimum over
  // (its visibility is +inf); prepare_surface never lets one through.
  if (st != blayer::NormalStatus::kDegenerateFan && (!std::isfinite(pn.visibility[0]) || !std::isfinite(pn.normality[0])))
    broken("non-finite visibility or normality");
  const bool claims_visible = st == blayer::NormalStatus::kOk || st == blayer::NormalStatus::kNonUnique ||
                              st == blayer::NormalStatus::kVisibilityConstrained;
  const bool exact_method = method == blayer::NormalMethod::kMostNormal || method == blayer::NormalMethod::kMostVisible;
  if (exact_method && claims_visible && !(pn.visibility[0] > 0.0))
    broken(std::string("status ") + blayer::normal_status_name(st) + " with visibility " +
           std::to_string(pn.visibility[0]));
  return 0;
}
