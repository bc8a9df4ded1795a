// The growth-law options of the command line (layers, first-height, growth-ratio,
// total-thickness, last-height, relative-heights), shared by extrude and check --wall.
#pragma once

#include "blayer/extruder/growth_law.h"
#include "parameters.h"

namespace blayer {

inline GrowthLaw growth_law_options(const ParamValues& p) {
  GrowthLaw g;
  g.layers = p.get_int("layers");
  g.first_height = p.get_real("first-height");
  g.growth_ratio = p.get_real("growth-ratio");
  g.total_thickness = p.get_real("total-thickness");
  g.last_height = p.get_real("last-height");
  g.relative = p.is_set("relative-heights") && p.get_bool("relative-heights");
  return g;
}

// Whether the user gave any height (the default first height applies otherwise).
inline bool any_height_given(const ParamValues& p) {
  return p.is_set("first-height") || p.is_set("total-thickness") || p.is_set("last-height");
}

}  // namespace blayer
