#include "blayer/extruder/growth_law.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "blayer/core/errors.h"

namespace blayer {

namespace {

// Two given quantities that must agree (N == 1: first == last == total) are equal when
// they differ by less than this relative amount: values typed in decimal carry ~1e-15
// relative rounding, so 1e-9 accepts every honest pair and rejects real contradictions.
constexpr double kConsistencyRelTol = 1e-9;

// The unknown ratio is searched in [exp(-kLogRatioBound), exp(kLogRatioBound)]; beyond
// that the heights span more than 17 orders of magnitude per layer, which no mesh needs.
constexpr double kLogRatioBound = 40.0;

bool given(double v) { return v > 0.0; }

void check_value(const char* name, double v) {
  if (!std::isfinite(v) || v < 0.0) {
    std::ostringstream m;
    m << "growth law: " << name << " = " << v << " must be a finite value >= 0 (0 means derive it)";
    throw InputError(m.str());
  }
}

// sum_{k<n} r^k; may overflow to infinity for huge r, which compares correctly.
double geometric_sum(double r, int n) {
  double s = 0.0, p = 1.0;
  for (int k = 0; k < n; ++k) {
    s += p;
    p *= r;
  }
  return s;
}

// Ratio r with geometric_sum(r, n) == target (target > 1, n > 1). The sum grows
// strictly with r, from 1 (r -> 0) to infinity.
double solve_ratio(double target, int n, const char* what) {
  double lo = -kLogRatioBound, hi = kLogRatioBound;
  if (geometric_sum(std::exp(lo), n) > target || geometric_sum(std::exp(hi), n) < target) {
    std::ostringstream m;
    m << "growth law: no growth ratio in [e^-" << kLogRatioBound << ", e^" << kLogRatioBound << "] fits " << what
      << " with " << n << " layers; check the given heights";
    throw InputError(m.str());
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (geometric_sum(std::exp(mid), n) < target ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

bool nearly_equal(double a, double b) { return std::fabs(a - b) <= kConsistencyRelTol * std::max(a, b); }

}  // namespace

ResolvedGrowthLaw resolve_growth_law(const GrowthLaw& law) {
  const int n = law.layers;
  if (n < 1 || n > kMaxLayers) {
    std::ostringstream m;
    m << "growth law: layers = " << n << " must be in [1, " << kMaxLayers << "]";
    throw InputError(m.str());
  }
  check_value("first_height", law.first_height);
  check_value("last_height", law.last_height);
  check_value("total_thickness", law.total_thickness);
  check_value("growth_ratio", law.growth_ratio);

  const bool gf = given(law.first_height), gl = given(law.last_height), gt = given(law.total_thickness);
  const int n_heights = int(gf) + int(gl) + int(gt);
  double ratio = law.growth_ratio;
  if (n_heights == 0) {
    throw InputError(
        "growth law: give at least one of first_height, last_height, total_thickness (plus optionally "
        "growth_ratio, default " + std::to_string(kDefaultGrowthRatio) + ")");
  }
  if (n_heights == 1 && !given(ratio)) ratio = kDefaultGrowthRatio;
  if (n_heights + int(given(ratio)) != 2) {
    throw InputError(
        "growth law: give exactly two of first_height, last_height, total_thickness, growth_ratio "
        "(the others are derived); got " + std::to_string(n_heights + int(given(ratio))));
  }

  double first = 0.0;
  if (gf && given(ratio)) {
    first = law.first_height;
  } else if (gl && given(ratio)) {
    first = law.last_height / std::pow(ratio, n - 1);
  } else if (gt && given(ratio)) {
    first = law.total_thickness / geometric_sum(ratio, n);
  } else if (gf && gl) {
    if (n == 1) {
      if (!nearly_equal(law.first_height, law.last_height))
        throw InputError("growth law: with 1 layer first_height and last_height must be equal");
      ratio = 1.0;
    } else {
      ratio = std::pow(law.last_height / law.first_height, 1.0 / (n - 1));
    }
    first = law.first_height;
  } else if (gf && gt) {
    if (n == 1) {
      if (!nearly_equal(law.first_height, law.total_thickness))
        throw InputError("growth law: with 1 layer first_height and total_thickness must be equal");
      ratio = 1.0;
    } else {
      if (law.total_thickness <= law.first_height)
        throw InputError("growth law: total_thickness must exceed first_height when layers > 1");
      ratio = solve_ratio(law.total_thickness / law.first_height, n, "first_height and total_thickness");
    }
    first = law.first_height;
  } else {  // last and total
    if (n == 1) {
      if (!nearly_equal(law.last_height, law.total_thickness))
        throw InputError("growth law: with 1 layer last_height and total_thickness must be equal");
      ratio = 1.0;
    } else {
      if (law.total_thickness <= law.last_height)
        throw InputError("growth law: total_thickness must exceed last_height when layers > 1");
      // total / last = sum_k (1/r)^k: solve for 1/r.
      ratio = 1.0 / solve_ratio(law.total_thickness / law.last_height, n, "last_height and total_thickness");
    }
    first = law.last_height / std::pow(ratio, n - 1);
  }

  ResolvedGrowthLaw out;
  out.layers = n;
  out.growth_ratio = ratio;
  out.relative = law.relative;
  out.heights.resize(n);
  double h = first, total = 0.0;
  for (int k = 0; k < n; ++k) {
    out.heights[k] = h;
    total += h;
    h *= ratio;
  }
  if (!std::isfinite(total) || !(out.heights.back() > 0.0))
    throw InputError("growth law: the derived heights overflow or underflow; check the ratio and layer count");
  out.first_height = out.heights.front();
  out.last_height = out.heights.back();
  out.total_thickness = total;
  return out;
}

GrowthLaw with_default_first_height(GrowthLaw law, double wall_diagonal, std::string* note) {
  note->clear();
  if (law.first_height != 0.0 || law.last_height != 0.0 || law.total_thickness != 0.0) return law;
  if (law.relative)
    throw InputError("growth law: relative heights need first_height, total_thickness or last_height");
  law.first_height = kDefaultFirstHeightFraction * wall_diagonal;
  static_assert(kDefaultFirstHeightFraction == 2e-4, "the note quotes the fraction as written");
  char buf[160];
  std::snprintf(buf, sizeof buf, "no height given: first-height = %.6g (2e-4 x bounding-box diagonal)",
                law.first_height);
  *note = buf;
  return law;
}

std::string describe_growth_law(const ResolvedGrowthLaw& law) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "N=%d first=%.6g last=%.6g total=%.6g ratio=%.6g (%s)", law.layers,
                law.first_height, law.last_height, law.total_thickness, law.growth_ratio,
                law.relative ? "relative to local edge length" : "absolute");
  return buf;
}

}  // namespace blayer
