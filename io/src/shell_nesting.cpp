#include "blayer/io/shell_nesting.h"

#include <algorithm>
#include <cmath>

#include "blayer/core/assert.h"
#include "blayer/core/point_in_surface.h"

namespace blayer {

namespace {

struct Bounds {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL};
  Vec3 hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  bool contains(const Bounds& o) const {
    for (int k = 0; k < 3; ++k)
      if (o.lo[k] < lo[k] || o.hi[k] > hi[k]) return false;
    return true;
  }
  double volume() const { return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
};

// Each component as a surface of its own, with its points renumbered: ray parity
// against one component costs its own triangles only.
std::vector<TriSurface> split_components(const TriSurface& s, const SurfaceComponents& comps) {
  std::vector<TriSurface> parts(comps.count);
  std::vector<int> local(s.points.size(), -1), owner(s.points.size(), -1);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const int c = comps.of_triangle[t];
    TriSurface& part = parts[c];
    Triangle lt;
    for (int k = 0; k < 3; ++k) {
      const int v = s.triangles[t][k];
      if (owner[v] != c) {
        owner[v] = c;
        local[v] = static_cast<int>(part.points.size());
        part.points.push_back(s.points[v]);
      }
      lt[k] = local[v];
    }
    part.triangles.push_back(lt);
  }
  return parts;
}

}  // namespace

ShellNesting nest_closed_components(const TriSurface& s, const SurfaceComponents& comps,
                                    const std::vector<char>& closed) {
  BLAYER_ASSERT(static_cast<int>(closed.size()) == comps.count);
  ShellNesting out;
  out.depth.assign(comps.count, 0);
  out.enclosing.assign(comps.count, -1);
  const std::vector<TriSurface> parts = split_components(s, comps);
  std::vector<Bounds> box(comps.count);
  for (int c = 0; c < comps.count; ++c)
    for (const Vec3& p : parts[c].points) box[c].add(p);
  const double scale = bounding_box_diagonal(s.points);
  for (int c = 0; c < comps.count; ++c) {
    if (!closed[c] || parts[c].triangles.empty()) continue;
    const Triangle& t = parts[c].triangles.front();
    const Vec3 probe = (1.0 / 3.0) * (parts[c].points[t[0]] + parts[c].points[t[1]] + parts[c].points[t[2]]);
    bool decided = true;
    for (int d = 0; d < comps.count; ++d) {
      if (d == c || !closed[d] || !box[d].contains(box[c])) continue;
      const Containment in = point_in_closed_surface(parts[d], probe, scale);
      if (in == Containment::kUndecided) decided = false;
      if (in != Containment::kInside) continue;
      ++out.depth[c];
      // The innermost enclosing shell is the one with the smallest box (nested boxes
      // shrink strictly inwards, since the shells do not touch).
      if (out.enclosing[c] < 0 || box[d].volume() < box[out.enclosing[c]].volume()) out.enclosing[c] = d;
    }
    if (!decided) out.undecided.push_back(c);
  }
  return out;
}

}  // namespace blayer
