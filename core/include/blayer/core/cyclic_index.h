// Indices around a cycle of n items (the corners of a face, the link vertices of a
// fan), wrapped by a comparison: a modulo by a count known only at run time is an
// integer division, which was a measurable share of the per-face and per-cell loops
// that step around such cycles.
#pragma once

namespace blayer {

// i + 1 wrapped to [0, n), for 0 <= i < n.
inline int cyclic_next(int i, int n) { return i + 1 == n ? 0 : i + 1; }
// i - 1 wrapped to [0, n), for 0 <= i < n.
inline int cyclic_previous(int i, int n) { return i == 0 ? n - 1 : i - 1; }
// i wrapped to [0, n), for -n <= i < 2 n.
inline int cyclic_wrap(int i, int n) { return i < 0 ? i + n : i < n ? i : i - n; }

}  // namespace blayer
