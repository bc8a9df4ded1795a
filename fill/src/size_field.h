// Graded size field s(x) = min_i (h_i + slope * |x - p_i|) over sites p_i with sizes h_i:
// the largest field that equals (at most) h_i at the sites and grows no faster than
// `slope` per unit length. Exact minimum via a k-d tree with branch and bound.
#pragma once

#include <algorithm>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer::fill_detail {

class SizeField {
 public:
  // sites and sizes have equal, non-zero length; slope >= 0 (BLAYER_ASSERT).
  SizeField(std::vector<Vec3> sites, std::vector<double> sizes, double slope);

  double operator()(const Vec3& x) const;

  // Smallest and largest h_i over the sites.
  double min_site_size() const { return *std::min_element(sizes_.begin(), sizes_.end()); }
  double max_site_size() const { return *std::max_element(sizes_.begin(), sizes_.end()); }

 private:
  struct Node {
    Vec3 lo, hi;      // bounding box of the node's sites
    double min_size;  // smallest h_i below the node
    int begin, end;   // range in order_
    int left = -1, right = -1;
  };
  int build(int begin, int end);
  void query(int node, const Vec3& x, double& best) const;

  std::vector<Vec3> sites_;
  std::vector<double> sizes_;
  double slope_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace blayer::fill_detail
