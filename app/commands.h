// The subcommands of the blayer executable. Each returns the process exit status:
// 0 success, 1 bad input or failure, 2 (check only) an invalid mesh, 3 (extrude only)
// the mesh is valid and written but fewer columns than --require-thickness asks reach
// 90 % of the thickness.
#pragma once

#include "parameters.h"

namespace blayer {

constexpr int kExitThicknessNotReached = 3;

int run_normals_command(const ParamValues& params);
int run_extrude_command(const ParamValues& params);
int run_check_command(const ParamValues& params);

}  // namespace blayer
