#include "tetgen_isolated.h"

#include <exception>

#include "blayer/core/errors.h"
#include "blayer/fill/run_isolated.h"

namespace blayer::fill_detail {

TetgenMesh run_tetgen_isolated(const TetgenPlc& plc, const std::string& switches, double timeout_seconds,
                               const TetgenRunLabel& label) {
  IsolatedOutcome o;
  try {
    o = run_isolated([&plc, &switches] { return encode(run_tetgen(plc, switches)); }, timeout_seconds);
  } catch (const ChildProcessError& e) {
    throw InputError(label.prefix + e.what() + label.crash_hint);
  }
  if (o.kind == IsolatedOutcome::Kind::kThrewInt) throw InputError(label.prefix + describe_tetgen_error(o.thrown_int));
  if (o.kind != IsolatedOutcome::Kind::kOk) throw InputError(label.prefix + o.data);
  try {
    return decode(o.data);
  } catch (const std::exception& e) {
    throw InputError(label.prefix + e.what());
  }
}

}  // namespace blayer::fill_detail
