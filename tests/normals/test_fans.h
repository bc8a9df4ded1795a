// The public test fans T1-T11 of docs/normals.md built from their constructions (not
// the 9-digit rounded table), plus helpers shared by the normals tests.
#pragma once

#include <cmath>
#include <vector>

#include "blayer/core/vec3.h"
#include "blayer/normals/fan_geometry.h"

namespace blayer {
namespace testing_fans {

constexpr double kPi = 3.14159265358979323846;
inline double deg(double d) { return d * kPi / 180.0; }

struct TestFan {
  const char* name;
  std::vector<Vec3> ring;  // around p = 0, closed
};

inline Vec3 azimuth(double r, double a_deg) { return {r * std::cos(deg(a_deg)), r * std::sin(deg(a_deg)), 0.0}; }

inline std::vector<TestFan> public_fans() {
  std::vector<TestFan> f;
  f.push_back({"T1", {azimuth(1, 0), azimuth(0.6, 50), azimuth(1.4, 110), azimuth(0.8, 170), azimuth(1.2, 230),
                      azimuth(0.5, 300)}});
  f.push_back({"T2", {{0, -1, 0}, {0, -1, -1}, {0, 0, -1}, {-1, 0, 0}, {-1, -1, 0}}});
  f.push_back({"T3", {{0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {1, 0, 0}, {1, 1, 0}}});
  f.push_back({"T4", {{0, 1, 0}, {-1, 1, 0}, {-1, -0.5, 0}, {0, -1, 0}, {0, -1, -1}, {0, 0.8, -1}}});
  {
    const Vec3 t{0, 1, 0};
    const Vec3 su{-std::cos(deg(15)), 0, std::sin(deg(15))}, sl{-std::cos(deg(15)), 0, -std::sin(deg(15))};
    f.push_back({"T5", {t, 1.3 * (std::cos(deg(70)) * t + std::sin(deg(70)) * su), -t,
                        0.7 * (std::cos(deg(110)) * (-t) + std::sin(deg(110)) * sl)}});
  }
  f.push_back({"T6", {{0, -1, 0}, {1, -1, 0}, {1, 0.3, 0}, {0, 1, 0}, {0, 1, 1}, {0, -0.2, 1.3}}});
  {
    const Vec3 t{0, 1, 0};
    const Vec3 su{-std::cos(deg(5)), 0, std::sin(deg(5))}, sl{-std::cos(deg(5)), 0, -std::sin(deg(5))};
    std::vector<Vec3> r;
    for (double phi : {0.0, 45.0, 90.0, 135.0, 180.0}) r.push_back(std::cos(deg(phi)) * t + std::sin(deg(phi)) * su);
    for (double phi : {60.0, 120.0}) r.push_back(std::cos(deg(phi)) * (-t) + std::sin(deg(phi)) * sl);
    f.push_back({"T7", r});
  }
  {
    std::vector<Vec3> r;
    for (int j = 0; j < 6; ++j) {
      const double th = deg(60.0 * j);
      r.push_back({std::cos(th), std::sin(th), 0.5 * std::cos(3 * th)});
    }
    f.push_back({"T8", r});
  }
  {
    std::vector<Vec3> r;
    auto cone = [](double s, double psi) {
      return Vec3{s * std::sqrt(3.0) * std::cos(deg(psi)), s * std::sqrt(3.0) * std::sin(deg(psi)), -s};
    };
    for (int j = 0; j <= 6; ++j) r.push_back(cone(1, 15.0 * j));
    r.push_back(cone(2, 180));
    r.push_back(cone(2, 270));
    f.push_back({"T9", r});
  }
  f.push_back({"T10", {{0, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, 0, 0}, {-1, 0, 1}, {0, 0, 1}, {0, -1, 1}}});
  {
    const double t15 = std::tan(deg(15));
    f.push_back({"T11", {{0, -1, 0}, {-1, 0, -t15}, {-1, 0, t15}, {-1, -1, t15}}});
  }
  return f;
}

inline FanGeometry geometry(const std::vector<Vec3>& ring, bool closed = true) {
  return build_fan_geometry(Vec3{0, 0, 0}, ring, closed);
}

}  // namespace testing_fans
}  // namespace blayer
