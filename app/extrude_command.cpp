#include "commands.h"
#include "blayer/core/errors.h"
namespace blayer { int run_extrude_command(const ParamValues&) { throw InputError("extrude: not wired yet"); } }
