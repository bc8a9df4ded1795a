// The undirected edges of a triangle surface with the triangles using each, classified
// for the checks that the surface input and the tetrahedral fill both make: open
// (boundary) edges, non-manifold edges and inconsistent orientation.
//
// An edge {lo, hi} (lo < hi) is used by every triangle that has lo and hi as
// consecutive corners; the use runs forward when the triangle goes lo -> hi.
//   kManifold      two uses in opposite directions (consistent winding)
//   kBoundary      one use (a hole's rim, or the border of an open surface)
//   kNonManifold   more than two uses
//   kInconsistent  two uses in the same direction (neighbours with opposite winding)
// A closed, edge-manifold, consistently oriented surface has only kManifold edges.
//
// Cost O(#F) (counting sort by lo, then each vertex's few edges by hi); the edge list
// is sorted by (lo, hi) and, within an edge, uses are in ascending triangle order.
// Preconditions (BLAYER_ASSERT): triangle indices lie in [0, #V); a triangle that
// repeats a point has a degenerate edge {v, v}, which is skipped.
#pragma once

#include <array>
#include <vector>

#include "blayer/core/surface.h"

namespace blayer {

enum class EdgeKind { kManifold, kBoundary, kNonManifold, kInconsistent };

struct SurfaceEdge {
  int lo = 0, hi = 0;                   // point indices, lo < hi
  int n_uses = 0;                       // triangles using the edge
  std::array<int, 2> triangle{-1, -1};  // the first two users, ascending (-1: none)
  std::array<bool, 2> forward{false, false};  // whether that user runs lo -> hi
  EdgeKind kind = EdgeKind::kManifold;
};

struct EdgeTopology {
  std::vector<SurfaceEdge> edges;  // sorted by (lo, hi)
  int n_boundary = 0;
  int n_non_manifold = 0;
  int n_inconsistent = 0;

  bool closed_manifold_oriented() const { return n_boundary == 0 && n_non_manifold == 0 && n_inconsistent == 0; }
};

EdgeTopology build_edge_topology(const TriSurface& s);

}  // namespace blayer
