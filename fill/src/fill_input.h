// Input checks of the tetrahedral fill and the envelope's bodies (tet_fill.h states the
// contract these enforce). Every failure is an InputError naming the problem.
#pragma once

#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/surface_components.h"
#include "blayer/fill/tet_fill.h"

namespace blayer::fill_detail {

// Ranges of the options and their combination with the region.
void check_fill_options(const FillOptions& opt);

// Throws unless s is a closed, edge-manifold, consistently oriented surface of valid,
// non-degenerate triangles with finite points. `what` names it in messages.
void check_closed_surface(const TriSurface& s, const std::string& what);

// The envelope's closed components with their signed volumes: positive for a body
// (normals away from it: it gets a hole point), negative for a wall around the domain
// (region inside only). Throws when the orientation does not fit the region.
struct EnvelopeParts {
  SurfaceComponents components;
  std::vector<double> volume;  // per component
};
EnvelopeParts classify_envelope_parts(const TriSurface& envelope, FillOptions::Region region);

std::string format_point(const Vec3& p);

}  // namespace blayer::fill_detail
