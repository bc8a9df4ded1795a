#include "blayer/core/symmetry_plane.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace blayer {

std::string SymmetryPlane::describe() const {
  char buf[160];
  if (axis >= 0)
    std::snprintf(buf, sizeof buf, "%c = %.17g", "xyz"[axis], offset);
  else
    std::snprintf(buf, sizeof buf, "(%.9g %.9g %.9g) . x = %.17g", normal[0], normal[1], normal[2], offset);
  return buf;
}

bool parse_symmetry_plane(const std::string& text, SymmetryPlane* out) {
  std::string compact;
  for (char c : text)
    if (c != ' ' && c != '\t') compact += c;
  if (compact.size() >= 3 && compact[1] == '=' && (compact[0] == 'x' || compact[0] == 'y' || compact[0] == 'z')) {
    std::size_t used = 0;
    double c = 0.0;
    try {
      c = std::stod(compact.substr(2), &used);
    } catch (...) {
      return false;
    }
    if (used != compact.size() - 2 || !std::isfinite(c)) return false;
    SymmetryPlane p;
    p.axis = compact[0] - 'x';
    p.normal = {0.0, 0.0, 0.0};
    p.normal[p.axis] = 1.0;
    p.offset = c;
    *out = p;
    return true;
  }
  std::istringstream in(text);
  double a = 0, b = 0, c = 0, d = 0;
  std::string rest;
  if (!(in >> a >> b >> c >> d) || (in >> rest)) return false;
  const Vec3 n{a, b, c};
  const double len = norm(n);
  if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(d)) return false;
  SymmetryPlane p;
  p.normal = (1.0 / len) * n;
  p.offset = d / len;
  for (int k = 0; k < 3; ++k)  // a coordinate plane given as "0 1 0 c" is one
    if (std::fabs(p.normal[k]) == 1.0) {
      p.axis = k;
      p.offset = p.normal[k] * p.offset;
      p.normal[k] = 1.0;
    }
  *out = p;
  return true;
}

}  // namespace blayer
