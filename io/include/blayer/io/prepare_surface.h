// Turning what a file holds into a wall surface blayer can extrude: triangulation of
// polygons, every input check, and orientation towards the fluid.
//
// Checks, in order (each problem names the file, the element index in the file and the
// problem; one stage's problems are all reported before the next stage runs):
//   1. no faces; non-finite coordinates; coordinates beyond kMaxCoordinateMagnitude;
//      faces with fewer than 3 vertices, out-of-range or repeated vertex indices;
//   2. degenerate (zero-area) triangles; duplicate triangles; edges shared by more than
//      two triangles (non-manifold edges); a symmetry plane that does not make a clean
//      half model; open boundary edges (holes), unless open surfaces are allowed or they
//      lie in the symmetry plane; neighbours with opposite winding (inconsistent
//      orientation);
//   3. vertices used by no triangle; vertices whose triangles form more than one fan
//      (non-manifold vertices);
//   4. closed components (and a half model's components, closed by the plane)
//      enclosing no volume;
//   5. self-intersections (two triangles of one component that cross or touch away from
//      their shared vertices) and intersecting components (triangles of two components
//      that do), decided exactly (surface_intersections.h), listed with both triangles,
//      their vertices and a point near where they meet;
//   6. closed components whose nesting ray parity cannot decide (shell_nesting.h).
// Orientation: each closed component is oriented so that its triangles' normals point
// into the fluid, decided by its nesting depth (shell_nesting.h): with --side outward a
// body's skin points outward and a cavity inside a body points into the cavity; with
// --side inward a duct's wall points inward and a body inside the duct outward.
// Components are flipped as needed, with a note, and nested ones get a note saying
// which side is fluid. Open surfaces keep the file's winding (reversed for --side
// inward), except half models: a surface whose open boundary lies in a symmetry plane
// (symmetry_detection.h) has its boundary snapped onto the plane, and each of its
// components is oriented as if closed by the plane (its signed volume taken about a
// point of the plane, where the cut adds nothing) at nesting depth 0: only fully
// closed components are tested for nesting, and only inside each other.
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

// Largest accepted |coordinate|. Areas and normals multiply four coordinate differences
// (a squared cross product); below 1e75 even (2 x 1e75)^4 = 1.6e301 stays under
// double's 1.8e308, so no geometric computation overflows. No model in any length unit
// comes near it; a file that does holds garbage or a unit error.
inline constexpr double kMaxCoordinateMagnitude = 1e75;

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
