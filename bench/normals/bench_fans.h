// The generated fans of the most-normal benchmarks, drawn the same way for each of them
// (most_normal_bench, most_normal_solve_once), so that their figures describe the same
// fans: wing-skin vertices of valence up to 6, CAD-like fans (tests/normals/cad_fans.h)
// above.
#pragma once

#include <cstddef>
#include <random>
#include <utility>
#include <vector>

#include "blayer/normals/fan_geometry.h"
#include "cad_fans.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace bench {

// The first `count` non-degenerate fans of valence k (ByValence takes 64); with `exact`,
// CAD-like fans of valence 12 or more are drawn with planar faces (offset 0).
inline std::vector<FanGeometry> fans_of_valence(int k, std::size_t count = 64, bool exact = false) {
  std::vector<FanGeometry> fans;
  std::mt19937 rng(4242u + static_cast<unsigned>(k));
  for (int t = 0; fans.size() < count && t < 4000; ++t) {
    std::vector<Vec3> ring;
    if (k <= 6) {
      // Wing skins: convex, saddle and near-flat quadric vertices with mesh jitter.
      std::uniform_real_distribution<double> u(0.0, 1.0);
      const double k1 = t % 3 == 0 ? 0.05 + u(rng) : 1e-3 * (u(rng) - 0.3);
      const double k2 = t % 3 == 1 ? -0.5 * u(rng) : 1e-3 * (u(rng) - 0.5);
      ring = testing_fans::quadric_fan(rng, k, k1, k2, 1e-3 * u(rng));
    } else {
      const double offset = exact ? 0.0 : (t % 3 == 0 ? 1e-5 : 1e-3);
      ring = testing_fans::cad_like_fan(rng, testing_fans::kCadShapes[t % 4], k, offset);
    }
    FanGeometry g = testing_fans::geometry(ring);
    if (!g.any_degenerate) fans.push_back(std::move(g));
  }
  return fans;
}

// The first 32 non-degenerate CAD-like fans of one shape and valence k, offsets 1e-5
// and 1e-3 in turn (ByShape: which shape the averages of ByValence come from), or none
// (`exact`: the faces planar, as a CAD tessellation gives the wall).
inline std::vector<FanGeometry> fans_of_shape(testing_fans::CadShape shape, int k, bool exact = false) {
  std::vector<FanGeometry> fans;
  std::mt19937 rng(4242u + static_cast<unsigned>(k));
  for (int t = 0; fans.size() < 32 && t < 2000; ++t) {
    const double offset = exact ? 0.0 : (t % 2 == 0 ? 1e-5 : 1e-3);
    FanGeometry g = testing_fans::geometry(testing_fans::cad_like_fan(rng, shape, k, offset));
    if (!g.any_degenerate) fans.push_back(std::move(g));
  }
  return fans;
}

}  // namespace bench
}  // namespace blayer
