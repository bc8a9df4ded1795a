// Layer heights from a growth law: the number of layers N plus any two of first height,
// last height, total thickness and growth ratio (snappyHexMesh's thickness models).
//
// Layer k (0 = at the wall) has height h_k = first * ratio^k, so
//   last  = first * ratio^(N-1)
//   total = first * (ratio^N - 1) / (ratio - 1)   (N * first when ratio == 1).
// The missing quantities are derived in closed form, or by bisection on log(ratio) when
// the ratio is the unknown (total is strictly monotonic in the ratio there).
#pragma once

#include <string>
#include <vector>

namespace blayer {

// Growth ratio applied when exactly one of first/last/total is given and the ratio is
// left unset (0): a common RANS choice that keeps neighbouring cell sizes within 20 %.
constexpr double kDefaultGrowthRatio = 1.2;

// Upper bound on the layer count; more layers than this is almost certainly a typo
// (e.g. a thickness typed into the layer field).
constexpr int kMaxLayers = 1000;

// Input of the growth law. A quantity is "given" when it is > 0; 0 means "derive".
// Exactly two of first_height, last_height, total_thickness and growth_ratio must be
// given, except that a single one of first/last/total together with an unset ratio
// uses kDefaultGrowthRatio.
//   layers           N >= 1, default 10
//   first_height     height of the wall layer
//   last_height      height of layer N-1
//   total_thickness  sum of all N heights
//   growth_ratio     h_{k+1} / h_k (dimensionless, > 0; 1 = uniform layers)
//   relative         false: heights in model length units;
//                    true: heights are multiples of the local mean edge length at each
//                    wall vertex (the extruder scales them per column).
struct GrowthLaw {
  int layers = 10;
  double first_height = 0.0;
  double growth_ratio = 0.0;
  double total_thickness = 0.0;
  double last_height = 0.0;
  bool relative = false;
};

// All four quantities once resolved, plus the per-layer heights (size N).
struct ResolvedGrowthLaw {
  int layers = 0;
  double first_height = 0.0;
  double last_height = 0.0;
  double total_thickness = 0.0;
  double growth_ratio = 1.0;
  bool relative = false;
  std::vector<double> heights;
};

// First-layer height when no height is given at all: this fraction of the wall's
// bounding-box diagonal, small enough for wall-resolved RANS on typical models.
constexpr double kDefaultFirstHeightFraction = 2e-4;

// A law with no height given (first_height, last_height and total_thickness all 0)
// gets first_height = kDefaultFirstHeightFraction x wall_diagonal, and *note says so,
// e.g. "no height given: first-height = 0.00034641 (2e-4 x bounding-box diagonal)".
// A law with any height given is returned unchanged and *note is cleared. Throws
// InputError for relative heights with no height given (the default is a length, not
// a multiple of the edge length).
GrowthLaw with_default_first_height(GrowthLaw law, double wall_diagonal, std::string* note);

// Resolves the law. Throws InputError (message names the fields and what to change)
// when N is out of [1, kMaxLayers], a value is negative or not finite, fewer or more
// than two quantities are given, or the given pair admits no positive ratio
// (e.g. total <= first for N > 1, first != last for N == 1).
ResolvedGrowthLaw resolve_growth_law(const GrowthLaw& law);

// One-line summary, e.g. "N=10 first=1e-05 last=5.16e-05 total=0.00026 ratio=1.2 (absolute)".
std::string describe_growth_law(const ResolvedGrowthLaw& law);

}  // namespace blayer
