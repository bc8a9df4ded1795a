// How a run's arrays use the heap: large arrays reuse freed heap memory, and freed memory
// goes back to the system once, after the march.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace blayer {

// Arrays up to this size come from the heap, larger ones from their own mappings. 32 MiB
// is the largest mmap threshold glibc accepts on 64-bit systems.
constexpr std::size_t kHeapArrayLimit = std::size_t{32} << 20;

// Whether a GLIBC_TUNABLES value sets malloc's mmap threshold itself.
inline bool tunables_choose_mmap_threshold(const char* tunables) {
  return tunables != nullptr && std::strstr(tunables, "glibc.malloc.mmap_threshold") != nullptr;
}

// Makes glibc's malloc serve arrays up to kHeapArrayLimit from the heap (unless
// GLIBC_TUNABLES chooses the threshold). By default every array above 128 KiB, until
// glibc raises the threshold as mappings are freed, is a fresh mapping that the kernel
// zeroes page by page when it is first written and takes back when it is freed, so each
// phase paid again for the pages the phase before had used. From the heap, the next
// phase's arrays reuse them: on the benchmark surfaces about half the page faults and
// 4-16 % of the wall time went, at the same peak (README, "Memory and huge pages").
inline void keep_arrays_in_heap() {
#if defined(__GLIBC__)
  if (!tunables_choose_mmap_threshold(std::getenv("GLIBC_TUNABLES")))
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHeapArrayLimit));
#endif
}

// Returns the heap's free pages to the system (glibc; elsewhere a no-op). Called once,
// when the march's working state (a third of its memory) has been freed: the check's
// and the writer's arrays then fit in the peak the march reached, while without it the
// freed state, split among live arrays, stayed resident under them (the perforated
// block's peak about 20 MB higher). Costs a walk over the free lists, and the faults of
// the pages it returns when they are used again.
inline void release_free_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace blayer
