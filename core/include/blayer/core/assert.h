// Levelled assertions for programmer errors (broken preconditions and invariants), in
// the manner of geogram's geo_assert / geo_debug_assert.
//
//   BLAYER_ASSERT(cond)            always compiled and evaluated, in every build type.
//                                  For checks whose cost is small next to the work of
//                                  the function that makes them (an O(1) test, or an
//                                  O(n) scan in front of O(n) work).
//   BLAYER_ASSERT_MSG(cond, text)  the same, with a sentence saying what went wrong.
//   BLAYER_EXPENSIVE_ASSERT(cond)  compiled and evaluated only when the build defines
//                                  BLAYER_EXPENSIVE_CHECKS (CMake option of the same
//                                  name; `scripts/test.sh --checked`). For checks that
//                                  would change the cost of the code they guard (a
//                                  whole-mesh invariant inside a loop, a second
//                                  computation by another method). Without the option
//                                  the condition is not evaluated at all.
//
// A failed assertion throws std::logic_error whose what() reads
//   "<file>:<line>: assertion failed: <condition>[: <text>]"
// so that a test can catch it and the CLI reports it as an internal failure (exit 1)
// instead of aborting. Bad user input is never an assertion: it is an InputError.
#pragma once

namespace blayer {

// True in builds with BLAYER_EXPENSIVE_CHECKS, so that tests can expect either behaviour.
#ifdef BLAYER_EXPENSIVE_CHECKS
inline constexpr bool kExpensiveChecks = true;
#else
inline constexpr bool kExpensiveChecks = false;
#endif

// Throws std::logic_error with the message described above; text may be null.
[[noreturn]] void assertion_failed(const char* condition, const char* file, int line, const char* text);

}  // namespace blayer

#define BLAYER_ASSERT(cond) \
  ((cond) ? static_cast<void>(0) : ::blayer::assertion_failed(#cond, __FILE__, __LINE__, nullptr))

#define BLAYER_ASSERT_MSG(cond, text) \
  ((cond) ? static_cast<void>(0) : ::blayer::assertion_failed(#cond, __FILE__, __LINE__, (text)))

#ifdef BLAYER_EXPENSIVE_CHECKS
#define BLAYER_EXPENSIVE_ASSERT(cond) BLAYER_ASSERT(cond)
#else
#define BLAYER_EXPENSIVE_ASSERT(cond) static_cast<void>(0)
#endif
