// One TetGen run in a child process (run_isolated.h), with every way it can fail turned
// into an InputError: used for both the self-intersection check (switch d) and the
// meshing run.
#pragma once

#include <string>

#include "tetgen_adapter.h"

namespace blayer::fill_detail {

// What a failure message says: "<prefix><reason>", plus crash_hint after a crash,
// abort or timeout of the child (TetGen's own error codes carry their own advice).
struct TetgenRunLabel {
  std::string prefix;
  std::string crash_hint;
};

TetgenMesh run_tetgen_isolated(const TetgenPlc& plc, const std::string& switches, double timeout_seconds,
                               const TetgenRunLabel& label);

}  // namespace blayer::fill_detail
