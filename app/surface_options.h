// Surface-reading options shared by the normals and extrude commands.
#pragma once

#include "blayer/core/errors.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/io/prepare_surface.h"
#include "parameters.h"

namespace blayer {

inline PrepareOptions surface_options(const ParamValues& params) {
  PrepareOptions opt;
  opt.side = params.get_string("side") == "inward" ? Side::kInward : Side::kOutward;
  opt.allow_open = params.get_bool("allow-open");
  const std::string plane = params.get_string("symmetry-plane");
  if (!plane.empty()) {
    if (!parse_symmetry_plane(plane, &opt.symmetry.plane))
      throw InputError("--symmetry-plane: expected x=C, y=C, z=C or \"a b c d\" (got '" + plane + "')");
    opt.symmetry.mode = SymmetryMode::kPlane;
  } else {
    opt.symmetry.mode = params.get_string("symmetry") == "none" ? SymmetryMode::kNone : SymmetryMode::kAuto;
  }
  return opt;
}

}  // namespace blayer
