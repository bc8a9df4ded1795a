// Ordered one-ring ("fan") of every vertex of an oriented triangle surface.
#pragma once

#include <cstddef>
#include <vector>

#include "blayer/core/surface.h"

namespace blayer {

// A fan's list of ids: a view into VertexFans' flat arrays, valid while they live. A
// vector per list cost a heap block each, with its header, and a 56-byte record per
// point, which a run holds for its whole march.
class IdRange {
 public:
  IdRange() = default;
  IdRange(const int* first, const int* last) : first_(first), last_(last) {}
  const int* begin() const { return first_; }
  const int* end() const { return last_; }
  std::size_t size() const { return static_cast<std::size_t>(last_ - first_); }
  bool empty() const { return first_ == last_; }
  int operator[](std::size_t i) const { return first_[i]; }

 private:
  const int* first_ = nullptr;
  const int* last_ = nullptr;
};

// The fan of vertex p: triangles (p, ring[j], ring[j+1]) in the surface's own winding,
// ordered so that consecutive triangles share the edge (p, ring[j+1]).
// closed: the ring wraps around (ring.size() == triangles.size());
// open (boundary vertex): ring.size() == triangles.size() + 1 and the first and last
// ring vertices lie on the boundary.
struct VertexFan {
  IdRange ring;
  IdRange triangles;
  bool closed = false;
};

// Every point's fan in flat arrays (the ids, and where each point's start): fans[v] is
// a view of point v's.
class FanTable {
 public:
  std::size_t size() const { return closed_.size(); }
  VertexFan operator[](std::size_t v) const {
    return {IdRange(ring_.data() + ring_start_[v], ring_.data() + ring_start_[v + 1]),
            IdRange(triangles_.data() + triangle_start_[v], triangles_.data() + triangle_start_[v + 1]),
            closed_[v] != 0};
  }

  // Appends the next point's fan (empty lists for a point without one).
  void append(const std::vector<int>& ring, const std::vector<int>& triangles, bool closed);
  void reserve(std::size_t points, std::size_t ids);

 private:
  std::vector<int> ring_start_{0}, ring_, triangle_start_{0}, triangles_;
  std::vector<char> closed_;
};

struct VertexFans {
  FanTable fans;                     // one per point; empty for unused points
  std::vector<int> non_manifold;     // points whose triangles do not form a single fan
};

// O(#F) construction. A vertex whose incident triangles form several fans, or that
// has inconsistent winding around it, is listed in non_manifold and gets an empty fan.
VertexFans build_vertex_fans(const TriSurface& s);

}  // namespace blayer
