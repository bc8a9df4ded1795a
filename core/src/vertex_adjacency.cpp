#include "blayer/core/vertex_adjacency.h"

#include <algorithm>

#include "blayer/core/assert.h"

namespace blayer {

namespace {

// u is v's neighbour exactly when v is u's (rows sorted).
[[maybe_unused]] bool is_symmetric(const CsrTable& nbr) {
  for (int v = 0; v < nbr.n_rows(); ++v)
    for (const int* u = nbr.begin(v); u != nbr.end(v); ++u)
      if (!std::binary_search(nbr.begin(*u), nbr.end(*u), v)) return false;
  return true;
}

}  // namespace

CsrTable vertex_triangles(const TriSurface& s) {
  const int nv = static_cast<int>(s.points.size());
  CsrTable c;
  c.start.assign(nv + 1, 0);
  for (const Triangle& t : s.triangles)
    for (int v : t) {
      BLAYER_ASSERT_MSG(v >= 0 && v < nv, "triangle refers to a point outside the surface");
      ++c.start[v + 1];
    }
  for (int v = 0; v < nv; ++v) c.start[v + 1] += c.start[v];
  c.items.resize(c.start[nv]);
  std::vector<int> next(c.start.begin(), c.start.end() - 1);
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int v : s.triangles[f]) c.items[next[v]++] = f;
  return c;
}

CsrTable vertex_neighbours(const TriSurface& s, const CsrTable& vtri) {
  const int nv = static_cast<int>(s.points.size());
  BLAYER_ASSERT_MSG(vtri.n_rows() == nv, "vertex_triangles belongs to another surface");
  // Two candidates per incident triangle, then sort and unique each vertex's run in
  // place: one pass over one buffer, no per-vertex allocations.
  CsrTable c;
  c.start.assign(nv + 1, 0);
  c.items.reserve(2 * vtri.items.size());
  for (int v = 0; v < nv; ++v) {
    const std::size_t begin = c.items.size();
    for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
      for (int u : s.triangles[*f])
        if (u != v) c.items.push_back(u);
    std::sort(c.items.begin() + begin, c.items.end());
    c.items.erase(std::unique(c.items.begin() + begin, c.items.end()), c.items.end());
    c.start[v + 1] = static_cast<int>(c.items.size());
  }
  c.items.shrink_to_fit();
  BLAYER_EXPENSIVE_ASSERT(is_symmetric(c));
  return c;
}

}  // namespace blayer
