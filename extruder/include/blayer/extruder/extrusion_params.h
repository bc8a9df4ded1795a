// The extrusion's parameters and the reasons a column may end early: plain data shared
// by the marching stages (extrude_layers.h describes how each parameter is used).
#pragma once

#include <optional>

#include "blayer/core/symmetry_plane.h"
#include "blayer/extruder/growth_law.h"
#include "blayer/normals/point_normals.h"
#include "blayer/quality/solver_acceptance.h"

namespace blayer {

// Why a column ended before layer N (written as the int point array `stop_reason`), or,
// for a column that kept its layers, what compressed it (`limit_reason`).
enum class StopReason : int {
  kNone = 0,        // reached all layers at the law's heights
  kCollision = 1,   // the new front would intersect itself, the previous front or the wall
  kQuality = 2,     // a new cell failed the exact corner-tet test or the solver-acceptance
                    // limits (solver_limits) even at reduced height
  kProximity = 3,   // another front or wall ahead of the marching column
  kVisibility = 4,  // no direction sees all incident front faces by min_visibility
  kWallGap = 5,     // the wall across a gap, seen along the wall direction before marching
  kAspectRatio = 6, // a layer would exceed max_layer_aspect x the local wall spacing
  kStepStretch = 7, // the step would exceed max_step_stretch x the layer height (a sharp
                    // convex edge or corner), so the column stands lower than planned
};
constexpr int kStopReasonCount = 8;
const char* stop_reason_name(StopReason r);

// How a column's direction evolves from layer to layer (update_step_directions).
enum class ColumnDirections : int {
  kKept = 0,        // straight along the smoothed wall direction while it sees the front
  kRecomputed = 1,  // the front's point normals, recomputed on every layer
};

// What a limit (gap, proximity, a failing cell) does to a column.
enum class LimitPolicy : int {
  kCompress = 0,   // keep the first height and N layers, compress the upper layers;
                   // end the column only when even uniform layers do not fit
  kTerminate = 1,  // keep the law's heights and end the column at the limit
};

// Parameters; each default is what the CLI shows in --help.
struct ExtrusionParams {
  // Layer count and heights (growth_law.h). The default law only fixes N = 10 and the
  // ratio; one of first_height / last_height / total_thickness must be set.
  GrowthLaw growth;
  // Point-normal method on every front (point_normals.h).
  NormalMethod normal_method = NormalMethod::kMostNormal;
  // Jacobi passes averaging each direction with its neighbours'; 0 disables smoothing.
  int normal_smoothing_iterations = 2;
  // Rings over which a height reduction ramps back to full height (0: no smoothing).
  int height_smoothing_rings = 3;
  // A column may cover at most this fraction of the gap ahead of it (0 < x <= 0.5: two
  // fronts growing towards each other meet in the middle).
  double proximity_safety = 0.45;
  // How directions evolve and what a limit does (see the enums above).
  ColumnDirections column_directions = ColumnDirections::kKept;
  LimitPolicy limit_policy = LimitPolicy::kCompress;
  // AFLR3-style layer end: a column ends before the first layer whose height exceeds
  // this multiple of the mean wall edge length at its point (aspect ratio of the
  // cell); 0 disables it.
  double max_layer_aspect = 0.0;
  // Smallest accepted visibility min_i n.f_i (cosine of the largest angle between the
  // step direction and an incident face normal); 0.05 is about 87 degrees.
  double min_visibility = 0.05;
  // Cap on the step stretch 1/V; a column with smaller V still steps, but ends less
  // than h above its steepest incident face.
  double max_step_stretch = 5.0;
  // Passes that first turn the columns of failing cells / colliding triangles towards
  // the mean direction of those triangles (keeping half their visibility) before any
  // layer is lowered; 0 goes straight to lowering.
  int direction_repair_passes = 2;
  // Exact per-layer intersection check of the new front (off: faster, no guarantee
  // that the envelope is free of self-intersections).
  bool check_collisions = true;
  // What every new cell must meet beside the exact test, measured as OpenFOAM's
  // checkMesh measures it (quality/solver_acceptance.h); a cell that breaks a limit
  // fails like an invalid one (kQuality). 0 disables a limit. In order:
  //   max_non_orthogonality_deg  89.99: inside checkMesh's error limit of 90 degrees;
  //   max_skewness               4: checkMesh's failure limit (internal faces);
  //   max_boundary_skewness      4: checkMesh applies the same 4 on the boundary;
  //   max_face_warp_deg          0 (off);
  //   face_pyramids              true: checkMesh's face pyramids;
  //   face_tets                  false: checkMesh -allGeometry's face tets.
  // front_checker.h says which faces each limit sees in a layer; docs/extrusion.md has
  // the measurements behind the defaults (lower non-orthogonality limits and the face
  // tets cost the pyHyp wings 9 % of their columns and more).
  AcceptanceLimits solver_limits{89.99, 4.0, 4.0, 0.0, true, false};
  // A half model's symmetry plane (io/symmetry_detection.h): the wall's boundary points
  // on it grow columns that stay in it (directions from the fan mirrored about the
  // plane, projected into it); every other column stays on the model's side, the plane
  // limiting it like a wall.
  std::optional<SymmetryPlane> symmetry;
  // Fans at sharp convex edges (fan_layout.h): a convex wall edge turning by more than
  // fan_angle_deg gets a fan of columns at its points, one per smooth sector along the
  // sector's own normal, with sub-normals so that neighbouring columns differ by at
  // most fan_max_sector_deg; 0 disables fans.
  double fan_angle_deg = 60.0;
  double fan_max_sector_deg = 30.0;
};

// Throws InputError naming the field when a parameter is out of its range.
void check_extrusion_params(const ExtrusionParams& p);

}  // namespace blayer
