#include "blayer/core/percentile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "blayer/core/assert.h"

namespace blayer {

std::vector<double> percentiles(std::vector<double> values, const std::vector<double>& qs) {
  for (std::size_t i = 0; i < qs.size(); ++i) {
    BLAYER_ASSERT_MSG(qs[i] >= 0.0 && qs[i] <= 1.0, "percentile ranks lie in [0, 1]");
    BLAYER_ASSERT_MSG(i == 0 || qs[i - 1] <= qs[i], "percentile ranks must be ascending");
  }
  BLAYER_EXPENSIVE_ASSERT(std::none_of(values.begin(), values.end(), [](double v) { return std::isnan(v); }));
  std::vector<double> out(qs.size(), std::numeric_limits<double>::quiet_NaN());
  if (values.empty()) return out;
  auto first = values.begin();
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const auto k = values.begin() + static_cast<std::ptrdiff_t>(std::floor(qs[i] * static_cast<double>(values.size() - 1)));
    std::nth_element(first, k, values.end());
    out[i] = *k;
    first = k;
  }
  return out;
}

double percentile(std::vector<double> values, double q) { return percentiles(std::move(values), {q}).front(); }

}  // namespace blayer
