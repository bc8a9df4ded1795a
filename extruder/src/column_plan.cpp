#include "blayer/extruder/column_plan.h"

#include <algorithm>
#include <cmath>

#include "blayer/core/assert.h"

namespace blayer {

namespace {

// The compressed ratio is bisected until the bracket is this relative width: a few ulps
// of a ratio near 1, so the budget is met to rounding.
constexpr double kRatioBisectionRelWidth = 1e-15;

// p (r + r^2 + ... + r^m)
double grown_sum(double p, double r, int m) {
  double s = 0.0, q = p;
  for (int i = 0; i < m; ++i) {
    q *= r;
    s += q;
  }
  return s;
}

// The largest r in [r_min, r_max] with grown_sum(p, r, m) <= budget (the sum grows
// with r); requires grown_sum(p, r_min, m) <= budget.
double fitting_ratio(double p, double r_min, double r_max, int m, double budget) {
  if (grown_sum(p, r_max, m) <= budget) return r_max;
  double lo = r_min, hi = r_max;
  for (int it = 0; it < 200 && hi - lo > kRatioBisectionRelWidth * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (grown_sum(p, mid, m) <= budget ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

void note_limit(ColumnPlan* plan, int v, StopReason why) {
  if (plan->limit[v] == StopReason::kNone) plan->limit[v] = why;
}

double ColumnPlan::cumulative(int v, int k) const {
  double s = 0.0;
  for (int j = 0; j <= k && j < n_layers; ++j) s += height(v, j);
  return s;
}

double ColumnPlan::remaining(int v, int k) const {
  double s = 0.0;
  for (int j = std::max(k, 0); j < planned_layers[v]; ++j) s += height(v, j);
  return s;
}

ColumnPlan plan_columns(const ResolvedGrowthLaw& law, const std::vector<double>& base) {
  const int nv = static_cast<int>(base.size());
  ColumnPlan p;
  p.n_layers = law.layers;
  p.growth_ratio = law.growth_ratio;
  p.heights.resize(static_cast<std::size_t>(nv) * law.layers);
  p.target_total.resize(nv);
  for (int v = 0; v < nv; ++v) {
    for (int k = 0; k < law.layers; ++k) p.height(v, k) = base[v] * law.heights[k];
    p.target_total[v] = base[v] * law.total_thickness;
  }
  p.planned_layers.assign(nv, law.layers);
  p.limit.assign(nv, StopReason::kNone);
  p.end_reason.assign(nv, StopReason::kNone);
  return p;
}

bool compress_from(ColumnPlan* plan, int v, int k, double budget, StopReason why) {
  BLAYER_ASSERT(k >= 0 && k <= plan->n_layers && budget >= 0.0);
  const int n = plan->planned_layers[v];
  if (k >= n || plan->remaining(v, k) <= budget) return false;
  note_limit(plan, v, why);
  if (k == 0) {
    const double first = plan->height(v, 0);
    if (budget < first) {
      plan->planned_layers[v] = 0;
      plan->end_reason[v] = why;
      return true;
    }
    if (n == 1) return false;
    compress_from(plan, v, 1, budget - first, why);
    return true;
  }
  const double p = plan->height(v, k - 1);
  const double first = plan->height(v, 0);
  const int m = n - k;
  // Growth from p: no ratio above the law's; below 1 only as far as keeps the top
  // layer at the first height.
  const double r_max = std::max(plan->growth_ratio, 1.0);
  const double r_min = std::min(1.0, std::pow(first / p, 1.0 / m));
  if (grown_sum(p, r_min, m) > budget) {
    const int fit = std::min(m, static_cast<int>(std::floor(budget / first)));
    for (int j = k; j < k + fit; ++j) plan->height(v, j) = first;
    plan->planned_layers[v] = k + fit;
    plan->end_reason[v] = why;
    return true;
  }
  const double r = fitting_ratio(p, r_min, r_max, m, budget);
  double h = p;
  for (int j = k; j < n; ++j) {
    h *= r;
    plan->height(v, j) = std::min(plan->height(v, j), std::max(h, first));
  }
  return true;
}

int layers_that_fit(const ColumnPlan& plan, int v, int k, double budget) {
  double sum = 0.0;
  int n = k;
  while (n < plan.planned_layers[v] && sum + plan.height(v, n) <= budget) sum += plan.height(v, n++);
  return n;
}

void lower_layer(ColumnPlan* plan, int v, int k, double height, StopReason why) {
  BLAYER_ASSERT_MSG(k > 0 && height >= plan->height(v, 0) && height <= plan->height(v, k),
                    "a layer is lowered to between the first height and its planned height");
  note_limit(plan, v, why);
  plan->height(v, k) = height;
  double h = height;
  for (int j = k + 1; j < plan->n_layers; ++j) {
    h *= std::max(1.0, plan->growth_ratio);
    plan->height(v, j) = std::min(plan->height(v, j), h);
  }
}

void end_column_after(ColumnPlan* plan, int v, int layers, StopReason why) {
  if (layers >= plan->planned_layers[v]) return;
  note_limit(plan, v, why);
  plan->planned_layers[v] = std::max(0, layers);
  plan->end_reason[v] = why;
}

}  // namespace blayer
