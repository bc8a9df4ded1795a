// Parsing with a third-party reader in a forked child process, so that a crash inside
// it (VTK's XML reader aborts or faults on some corrupt files, and allocates whatever a
// corrupt header claims) becomes an InputError instead of ending blayer.
//
// The child runs `parse` and nothing else, sends the soup (or the InputError's message)
// through a pipe and leaves with _exit. Only the calling thread exists in the child, so
// `parse` must not need other threads. fill/'s run_isolated does the same for TetGen;
// io cannot depend on fill (TetGen), hence this small one. Under AddressSanitizer the
// parse runs in the calling process (the .cpp says why).
#pragma once

#include <functional>
#include <string>

#include "blayer/io/read_surface.h"

namespace blayer::detail {

// Returns what parse() returned in the child; throws InputError naming `name` when it
// threw InputError (its message), anything else, or died (with the signal).
PolygonSoup parse_in_child(const std::function<PolygonSoup()>& parse, const std::string& name);

}  // namespace blayer::detail
