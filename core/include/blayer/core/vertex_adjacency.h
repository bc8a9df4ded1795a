// Compressed (CSR) per-vertex tables of a triangle surface: the triangles around each
// vertex and the vertices next to each vertex.
//
// Shapes: for #V points, start has #V + 1 entries and the items of vertex v are
// items[start[v] .. start[v + 1]). Unused points have empty lists.
// Both builders are O(#F) plus a sort of each vertex's few neighbours, and
// deterministic (the lists do not depend on thread timing or hashing).
// Precondition (BLAYER_ASSERT): every triangle index lies in [0, #V).
#pragma once

#include <vector>

#include "blayer/core/surface.h"

namespace blayer {

struct CsrTable {
  std::vector<int> start{0};
  std::vector<int> items;

  int n_rows() const { return static_cast<int>(start.size()) - 1; }
  const int* begin(int v) const { return items.data() + start[v]; }
  const int* end(int v) const { return items.data() + start[v + 1]; }
  int count(int v) const { return start[v + 1] - start[v]; }
};

// Triangles of each vertex, in ascending triangle order. A triangle that uses a vertex
// twice (only in unchecked input) is listed twice, once per corner.
CsrTable vertex_triangles(const TriSurface& s);

// Distinct vertices sharing a triangle with each vertex, ascending, the vertex itself
// excluded. vertex_triangles must be vertex_triangles(s).
CsrTable vertex_neighbours(const TriSurface& s, const CsrTable& vertex_triangles);

}  // namespace blayer
