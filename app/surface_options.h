// Surface-reading options shared by the normals and extrude commands.
#pragma once

#include "blayer/io/prepare_surface.h"
#include "parameters.h"

namespace blayer {

inline PrepareOptions surface_options(const ParamValues& params) {
  PrepareOptions opt;
  opt.side = params.get_string("side") == "inward" ? Side::kInward : Side::kOutward;
  opt.allow_open = params.get_bool("allow-open");
  return opt;
}

}  // namespace blayer
