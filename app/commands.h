// The subcommands of the blayer executable. Each returns the process exit status:
// 0 success, 1 bad input or failure, 2 (check only) an invalid mesh.
#pragma once

#include "parameters.h"

namespace blayer {

int run_normals_command(const ParamValues& params);
int run_extrude_command(const ParamValues& params);
int run_check_command(const ParamValues& params);

}  // namespace blayer
