#include "blayer/normals/weighted_normal.h"

#include <stdexcept>

namespace blayer {

Vec3 weighted_average_normal(const FanGeometry& g, NormalMethod method) {
  Vec3 sum{0.0, 0.0, 0.0};
  for (int i = 0; i < g.n_faces(); ++i) {
    if (g.degenerate[i]) continue;
    double w = 0.0;
    switch (method) {
      case NormalMethod::kUnit: w = 1.0; break;
      case NormalMethod::kArea: w = g.areas[i]; break;
      case NormalMethod::kInverseArea: w = 1.0 / g.areas[i]; break;
      case NormalMethod::kAngle: w = g.angles[i]; break;
      case NormalMethod::kMax: w = g.max_weights[i]; break;
      default: throw std::invalid_argument("weighted_average_normal: method is not a weighted average");
    }
    sum += w * g.face_normals[i];
  }
  return normalized(sum);
}

}  // namespace blayer
