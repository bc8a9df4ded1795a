// Parallel loop over point indices, in blocks (TBB). The marching stages use it for
// per-column work; every body writes only its own index, so results do not depend on
// the thread count.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace blayer {

template <class F>
void parallel_vertices(int n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v != r.end(); ++v) f(v);
  });
}

}  // namespace blayer
