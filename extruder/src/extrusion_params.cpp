#include "blayer/extruder/extrusion_params.h"

#include <cmath>
#include <string>

#include "blayer/core/errors.h"

namespace blayer {

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::kNone: return "none";
    case StopReason::kCollision: return "collision";
    case StopReason::kQuality: return "quality";
    case StopReason::kProximity: return "proximity";
    case StopReason::kVisibility: return "visibility";
    case StopReason::kWallGap: return "wall_gap";
    case StopReason::kAspectRatio: return "aspect_ratio";
    case StopReason::kStepStretch: return "step_stretch";
  }
  return "unknown";
}

void check_extrusion_params(const ExtrusionParams& p) {
  auto fail = [](const std::string& m) { throw InputError("extrusion parameters: " + m); };
  if (p.normal_smoothing_iterations < 0) fail("normal_smoothing_iterations must be >= 0");
  if (p.height_smoothing_rings < 0) fail("height_smoothing_rings must be >= 0");
  if (p.direction_repair_passes < 0) fail("direction_repair_passes must be >= 0");
  if (!(p.proximity_safety > 0.0 && p.proximity_safety <= 0.5))
    fail("proximity_safety must be in (0, 0.5] (two fronts growing towards each other meet in the middle)");
  if (!(p.max_layer_aspect >= 0.0) || !std::isfinite(p.max_layer_aspect))
    fail("max_layer_aspect must be >= 0 (0 disables the layer end)");
  if (!(p.min_visibility > 0.0 && p.min_visibility < 1.0)) fail("min_visibility must be in (0, 1)");
  if (!(p.max_step_stretch >= 1.0) || !std::isfinite(p.max_step_stretch)) fail("max_step_stretch must be >= 1");
  if (!(p.fan_angle_deg >= 0.0 && p.fan_angle_deg < 180.0)) fail("fan_angle_deg must be in [0, 180) (0 disables fans)");
  if (!(p.fan_max_sector_deg >= 5.0 && p.fan_max_sector_deg <= 90.0)) fail("fan_max_sector_deg must be in [5, 90]");
  const AcceptanceLimits& a = p.solver_limits;
  auto angle_ok = [](double x) { return x >= 0.0 && x <= 180.0; };
  if (!angle_ok(a.max_non_orthogonality_deg))
    fail("max_non_orthogonality_deg must be in [0, 180] degrees (0 disables the limit)");
  if (!angle_ok(a.max_face_warp_deg)) fail("max_face_warp_deg must be in [0, 180] degrees (0 disables the limit)");
  if (!(a.max_skewness >= 0.0) || !std::isfinite(a.max_skewness))
    fail("max_skewness must be >= 0 (0 disables the limit)");
  if (!(a.max_boundary_skewness >= 0.0) || !std::isfinite(a.max_boundary_skewness))
    fail("max_boundary_skewness must be >= 0 (0 disables the limit)");
}

}  // namespace blayer
