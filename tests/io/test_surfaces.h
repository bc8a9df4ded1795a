// Small closed surfaces as polygon soups, and as OFF text for the command-line tests.
#pragma once

#include <cstdio>
#include <string>
#include <utility>

#include "blayer/io/read_surface.h"

namespace blayer::testing {

// Axis-aligned box [lo, hi], 8 vertices (bottom 0-3, top 4-7 counter-clockwise seen from
// above) and 12 triangles, two per face in the order bottom, top, y = lo, x = hi,
// y = hi, x = lo; normals outward (reversed when inward).
inline PolygonSoup box(const Vec3& lo, const Vec3& hi, bool inward = false) {
  PolygonSoup s;
  s.points = {{lo[0], lo[1], lo[2]}, {hi[0], lo[1], lo[2]}, {hi[0], hi[1], lo[2]}, {lo[0], hi[1], lo[2]},
              {lo[0], lo[1], hi[2]}, {hi[0], lo[1], hi[2]}, {hi[0], hi[1], hi[2]}, {lo[0], hi[1], hi[2]}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& q : quads) {
    s.faces.push_back({q[0], q[1], q[2]});
    s.faces.push_back({q[0], q[2], q[3]});
  }
  if (inward)
    for (auto& f : s.faces) std::swap(f[1], f[2]);
  return s;
}

// Appends b's points and faces to a (b's indices shifted past a's points).
inline void append(PolygonSoup* a, const PolygonSoup& b) {
  const int base = static_cast<int>(a->points.size());
  a->points.insert(a->points.end(), b.points.begin(), b.points.end());
  for (auto f : b.faces) {
    for (int& v : f) v += base;
    a->faces.push_back(f);
  }
}

// The soup as OFF text, coordinates with 17 significant digits (exact round trip).
inline std::string off_text(const PolygonSoup& s) {
  std::string out = "OFF\n" + std::to_string(s.points.size()) + " " + std::to_string(s.faces.size()) + " 0\n";
  char buf[96];
  for (const Vec3& p : s.points) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out += buf;
  }
  for (const auto& f : s.faces) {
    out += std::to_string(f.size());
    for (int v : f) out += " " + std::to_string(v);
    out += "\n";
  }
  return out;
}

}  // namespace blayer::testing
