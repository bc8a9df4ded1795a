// The extrusion's parameters and the reasons a column may end early: plain data shared
// by the marching stages (extrude_layers.h describes how each parameter is used).
#pragma once

#include "blayer/extruder/growth_law.h"
#include "blayer/normals/point_normals.h"

namespace blayer {

// Why a column ended before layer N; written as the int point array `stop_reason`.
enum class StopReason : int {
  kNone = 0,        // reached all layers
  kCollision = 1,   // the new front would intersect itself, the previous front or the wall
  kQuality = 2,     // a new cell failed the exact corner-tet test even at reduced height
  kProximity = 3,   // the gap ahead (another front or wall) allows less than a useful layer
  kVisibility = 4,  // no direction sees all incident front faces by min_visibility
};
constexpr int kStopReasonCount = 5;
const char* stop_reason_name(StopReason r);

// The wall length a column's total height is capped against (max_height_to_edge_ratio).
enum class HeightCapLength : int {
  kShortestEdge = 0,  // shortest wall edge at the vertex
  kMeanEdge = 1,      // mean wall edge length at the vertex
  kFaceSize = 2,      // sqrt(2 x mean area of the incident wall triangles): the leg of a
                      // right isosceles triangle of that area, a size of the prism caps
                      // that, unlike the shortest edge, is not set by one short side
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
  // Column height cap relative to the shortest wall edge at the vertex, so that small
  // faces do not grow needles and columns on stretched triangles cannot overtake each
  // other sideways (on the pyHyp wing meshes, 2 gives full coverage at ~35 % of the
  // requested thickness, 5 gives 99 % coverage at ~50 %, 10 drops coverage to 89 %);
  // 0 disables the cap.
  double max_height_to_edge_ratio = 4.0;
  // Which wall length max_height_to_edge_ratio multiplies. The shortest edge stays the
  // default: measured (N=10, h1 = 2e-4 x diagonal, r = 1.2) as coverage / mean thickness
  // fraction on the pyHyp 717 wing, the pyHyp BWB and the 16k ONERA M6,
  //   shortest x4  1.000/0.43  1.000/0.47  1.000/0.99
  //   shortest x6  0.991/0.51  0.976/0.53  1.000/1.00  (min scaled Jacobian 0.0016 -> 0 on the 717)
  //   mean x3      0.981/0.75  0.838/0.71  1.000/0.99
  //   mean x4      0.979/0.80  0.830/0.73  1.000/1.00
  //   face x4      0.899/0.64  0.842/0.64  1.000/0.99
  //   no cap       0.939/0.97  0.772/0.85  1.000/1.00
  // every longer reference length loses the BWB's coverage to quality and collision
  // stops, and a larger ratio buys thickness with coverage and cell quality.
  HeightCapLength height_cap_length = HeightCapLength::kShortestEdge;
  // Smallest accepted visibility min_i n.f_i (cosine of the largest angle between the
  // step direction and an incident face normal); 0.05 is about 87 degrees.
  double min_visibility = 0.05;
  // Cap on the step stretch 1/V; a column with smaller V still steps, but ends less
  // than h above its steepest incident face.
  double max_step_stretch = 5.0;
  // A layer cut below this fraction of its height stops the column instead, so that no
  // sliver layers are made.
  double min_layer_fraction = 0.25;
  // Passes that first turn the columns of failing cells / colliding triangles towards
  // the mean direction of those triangles (keeping half their visibility) before any
  // height is cut; 0 goes straight to height reduction.
  int direction_repair_passes = 2;
  // Exact per-layer intersection check of the new front (off: faster, no guarantee
  // that the envelope is free of self-intersections).
  bool check_collisions = true;
};

// Throws InputError naming the field when a parameter is out of its range.
void check_extrusion_params(const ExtrusionParams& p);

}  // namespace blayer
