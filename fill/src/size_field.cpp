#include "size_field.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "blayer/core/assert.h"

namespace blayer::fill_detail {
namespace {

// Sites per leaf: small enough to prune well, large enough to keep the tree shallow.
constexpr int kLeafSize = 8;

double box_distance(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d = x[k] < lo[k] ? lo[k] - x[k] : (x[k] > hi[k] ? x[k] - hi[k] : 0.0);
    d2 += d * d;
  }
  return std::sqrt(d2);
}

}  // namespace

SizeField::SizeField(std::vector<Vec3> sites, std::vector<double> sizes, double slope)
    : sites_(std::move(sites)), sizes_(std::move(sizes)), slope_(slope) {
  BLAYER_ASSERT_MSG(!sites_.empty() && sites_.size() == sizes_.size(), "one size per site, at least one site");
  BLAYER_ASSERT(slope_ >= 0.0);
  order_.resize(sites_.size());
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.reserve(2 * sites_.size() / kLeafSize + 2);
  if (!sites_.empty()) build(0, static_cast<int>(sites_.size()));
}

int SizeField::build(int begin, int end) {
  Node n;
  n.begin = begin;
  n.end = end;
  n.lo = n.hi = sites_[order_[begin]];
  n.min_size = std::numeric_limits<double>::max();
  for (int i = begin; i < end; ++i) {
    const Vec3& p = sites_[order_[i]];
    for (int k = 0; k < 3; ++k) {
      n.lo[k] = std::min(n.lo[k], p[k]);
      n.hi[k] = std::max(n.hi[k], p[k]);
    }
    n.min_size = std::min(n.min_size, sizes_[order_[i]]);
  }
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(n);
  if (end - begin > kLeafSize) {
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (n.hi[k] - n.lo[k] > n.hi[axis] - n.lo[axis]) axis = k;
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int a, int b) { return sites_[a][axis] < sites_[b][axis]; });
    const int l = build(begin, mid);
    const int r = build(mid, end);
    nodes_[id].left = l;
    nodes_[id].right = r;
  }
  return id;
}

void SizeField::query(int id, const Vec3& x, double& best) const {
  const Node& n = nodes_[id];
  if (n.min_size + slope_ * box_distance(x, n.lo, n.hi) >= best) return;
  if (n.left < 0) {
    for (int i = n.begin; i < n.end; ++i) {
      const int s = order_[i];
      best = std::min(best, sizes_[s] + slope_ * norm(x - sites_[s]));
    }
    return;
  }
  // Nearer child first so that the bound tightens early.
  const Node& a = nodes_[n.left];
  const Node& b = nodes_[n.right];
  const bool left_first = box_distance(x, a.lo, a.hi) <= box_distance(x, b.lo, b.hi);
  query(left_first ? n.left : n.right, x, best);
  query(left_first ? n.right : n.left, x, best);
}

double SizeField::operator()(const Vec3& x) const {
  double best = std::numeric_limits<double>::max();
  if (!nodes_.empty()) query(0, x, best);
  return best;
}

}  // namespace blayer::fill_detail
