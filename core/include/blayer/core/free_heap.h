// Returning freed heap memory to the system between the phases of a run.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace blayer {

// Returns the heap's free pages to the system (glibc; elsewhere a no-op). glibc keeps
// freed memory resident for reuse, but the next phase's large arrays are fresh
// mappings that do not reuse it, so the two added up in the peak: the march's working
// state (a third of its memory) under the output arrays, the check's double metrics
// under the written file. Costs a walk over the free lists, milliseconds.
inline void release_free_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace blayer
