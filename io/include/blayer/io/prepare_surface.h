// Turning what a file holds into a wall surface blayer can extrude: triangulation of
// polygons, every input check, and orientation towards the fluid.
//
// Checks (each problem names the file, the element index in the file and the problem):
//   no faces; non-finite coordinates; faces with fewer than 3 vertices, out-of-range or
//   repeated vertex indices; degenerate (zero-area) triangles; duplicate triangles;
//   edges shared by more than two triangles (non-manifold edges); open boundary edges
//   (holes), unless open surfaces are allowed; neighbours with opposite winding
//   (inconsistent orientation); vertices used by no triangle; vertices whose triangles
//   form more than one fan (non-manifold vertices); closed components enclosing no volume.
// Orientation: each closed connected component is oriented so that its triangles'
// normals point into the fluid: outward (away from the enclosed volume) for --side
// outward, inward for --side inward. Components are flipped as needed, with a note.
// Open surfaces keep the file's winding (reversed for --side inward), except half models:
// a surface whose open boundary lies in a symmetry plane (symmetry_detection.h) has its
// boundary snapped onto the plane, and each of its components is oriented as if closed
// by the plane (its signed volume taken about a point of the plane, where the cut adds
// nothing).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/tolerances.h"
#include "blayer/io/read_surface.h"
#include "blayer/io/symmetry_detection.h"

namespace blayer {

enum class Side { kOutward, kInward };

struct PrepareOptions {
  Side side = Side::kOutward;
  bool allow_open = false;
  SymmetryRequest symmetry;  // auto: a half model's plane is found from its boundary
};

struct PreparedSurface {
  TriSurface surface;              // triangles' normals point into the fluid
  std::vector<std::string> notes;  // what was changed (triangulated, flipped), for the user
  bool closed = true;
  int n_flipped_components = 0;
  int n_components = 0;
  double enclosed_volume = 0.0;    // |signed volume| summed over closed components
  std::optional<SymmetryPlane> symmetry;  // the half model's plane, its points snapped on it
  int n_symmetry_points = 0;
  double symmetry_snap = 0.0;      // largest distance a boundary point was moved onto it
};

// Throws InputError listing the problems found (at most a few of each kind, with counts)
// when the surface cannot be used.
PreparedSurface prepare_surface(const PolygonSoup& soup, const std::string& file, const PrepareOptions& opt,
                                const Tolerances& tol = default_tolerances());

// read_polygon_soup followed by prepare_surface.
PreparedSurface load_surface(const std::string& path, const PrepareOptions& opt,
                             const Tolerances& tol = default_tolerances());

}  // namespace blayer
