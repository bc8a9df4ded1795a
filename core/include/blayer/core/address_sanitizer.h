// Whether this build runs under AddressSanitizer. GCC defines __SANITIZE_ADDRESS__;
// clang 14 (the fuzzers' compiler) does not, and answers __has_feature instead. Code
// that must behave differently under the sanitizer (no fork beside its allocator, no
// address-space limit beside its shadow memory) asks this one constant.
#pragma once

namespace blayer {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace blayer
