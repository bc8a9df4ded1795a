// Nearest-rank percentiles of a value array.
//
// The q-percentile (q in [0, 1]) of n values is the value of rank floor(q * (n - 1)) in
// ascending order (0-based): q = 0 is the minimum, q = 1 the maximum, q = 0.5 the lower
// median. No interpolation, so every reported percentile is a value that occurs.
// Selection (std::nth_element) instead of a sort: O(n) per call.
//
// Preconditions: every q in [0, 1] (BLAYER_ASSERT); no NaN among the values
// (BLAYER_EXPENSIVE_ASSERT: NaN has no rank). An empty array gives NaN.
#pragma once

#include <vector>

namespace blayer {

double percentile(std::vector<double> values, double q);

// Several percentiles at once; qs must be ascending (BLAYER_ASSERT). Each selection
// runs on the part above the previous rank, so k percentiles cost about one selection.
std::vector<double> percentiles(std::vector<double> values, const std::vector<double>& qs);

}  // namespace blayer
