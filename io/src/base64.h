// Base64 (RFC 4648 alphabet, '=' padding), the text encoding of VTK XML inline data.
// Written out rather than VTK's encoder, which makes a function call per three bytes:
// on the sliver wing's extrusion it took 553M instructions (3.0 % of the run), this one
// 358M, for the same text.
#pragma once

#include <cstddef>

namespace blayer {
namespace detail {

// Writes the 4 * ceil(n / 3) characters of the n bytes at `in` to `out`.
inline void encode_base64(const unsigned char* in, std::size_t n, unsigned char* out) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3, out += 4) {
    const unsigned v = (unsigned{in[i]} << 16) | (unsigned{in[i + 1]} << 8) | in[i + 2];
    out[0] = kDigits[v >> 18];
    out[1] = kDigits[(v >> 12) & 63];
    out[2] = kDigits[(v >> 6) & 63];
    out[3] = kDigits[v & 63];
  }
  if (i == n) return;
  const bool two = i + 2 == n;
  const unsigned v = (unsigned{in[i]} << 16) | (two ? unsigned{in[i + 1]} << 8 : 0u);
  out[0] = kDigits[v >> 18];
  out[1] = kDigits[(v >> 12) & 63];
  out[2] = two ? kDigits[(v >> 6) & 63] : '=';
  out[3] = '=';
}

}  // namespace detail
}  // namespace blayer
