// Layer fidelity: how faithfully a prism layer mesh honours the requested growth law,
// measured on the mesh alone, the way a RANS user judges it (is the first cell as high as
// asked, does the stack reach the requested thickness, where is it missing?).
//
// Input
//   mesh     a VolumeMesh in VTK node order: wedges 0-1-2 / 3-4-5 with column edges
//            0-3, 1-4, 2-5; hexahedra 0-1-2-3 / 4-5-6-7 with column edges 0-4, 1-5, 2-6,
//            3-7; pyramids closing a stopped column (y, y', z', z, x), the quad being
//            the side face of two growing columns y, z, with column edges 0-1 and 2-3
//            (extruder/layer_cells.h). Tets carry no column edge (a fill's tets would
//            otherwise pass for columns), so a column that grows only inside tets at
//            some layer (both other columns of every incident triangle stopped) ends
//            there for this measure.
//   wall     the wall surface, its points being mesh points 0..V-1 (#V by 3), its
//            triangles (#F by 3) oriented towards the fluid.
//   targets  the requested first height h1, total thickness T and layer count N.
// Columns
//   Every column edge from a wall point to a point off the wall starts a column (one per
//   wall point, or one per face sector where a fan of columns leaves a sharp edge;
//   a used wall point with none has one column without layers). A column is followed
//   through column edges, in either direction, from point to point, never back and
//   never onto a wall point, as long as an edge turns by less than 60 degrees from the
//   column's last segment (edges along a ridge or across a fan turn by about 90 and are
//   not followed); of several such edges the best aligned is taken and the column is
//   counted in n_branching (a layer mesh without fans has none). Per column: the layers
//   reached (edges followed), and for its first point above the wall and for its top
//     height_planes  min over the wall triangles the column stands on (those incident to
//                    its wall point; at a fan, those whose wall-layer wedge or pyramid
//                    holds the column's first edge) of the signed height above the
//                    triangle's plane: the quantity a growth law prescribes, and what
//                    the extruder's own report measures;
//     distance       the exact Euclidean distance to the nearest point of any wall
//                    triangle (a box tree, exact up to rounding): what a solver's wall
//                    distance sees, and the measure that notices a column leaning
//                    sideways or a layer too close to another part of the wall.
//   A column with no layer has first = top = its wall point, at height 0.
// Summaries
//   first_over_h1   (first height / h1) over the columns with at least one layer;
//   top_over_T      (top height / T) over all columns, 0 where nothing grew;
//   each in both measures as min, p1, p5, p50, p95, p99, max (percentiles by linear
//   interpolation between order statistics, i.e. numpy's default);
//   shares of the grown columns whose first height lies within 1 % and 10 % of h1
//   (|first/h1 - 1| <= 0.01, 0.1), of all columns reaching 0.9 T, and of all columns
//   having all N layers (complete); area_coverage: the share of wall area on triangles
//   all of whose points' columns are complete.
// Cost: O(#cells + #V log #F). Throws std::invalid_argument when the wall references a
// point outside the mesh or a target is not positive.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

struct LayerFidelityTargets {
  double first_height = 0.0;     // h1, length units of the mesh
  double total_thickness = 0.0;  // T
  int layers = 0;                // N
};

struct ColumnFidelity {
  int layers = 0;                    // column edges followed from the wall point
  std::int64_t top_point = -1;       // mesh point at the column's end (the wall point when layers == 0)
  double first_height_planes = 0.0;  // first point above the wall
  double first_distance = 0.0;
  double top_height_planes = 0.0;    // column top
  double top_distance = 0.0;
};

struct FidelityDistribution {
  int count = 0;
  double min = 0.0, p1 = 0.0, p5 = 0.0, p50 = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
};

// Order statistics of values (copied and sorted); all zero with count 0 when empty.
FidelityDistribution describe_distribution(std::vector<double> values);

struct LayerFidelity {
  std::vector<ColumnFidelity> columns;  // per wall point: its column with the fewest layers
                                        // (layers -1 for unused points)
  int n_columns = 0;                    // columns (one or more per wall point used by a triangle)
  int n_fan_points = 0;                 // wall points with more than one column
  int n_grown = 0;                      // columns with at least one layer
  int n_complete = 0;                   // columns with all N layers
  int n_branching = 0;                  // columns ended at a point with several onward edges

  FidelityDistribution first_over_h1_planes, first_over_h1_distance;
  FidelityDistribution top_over_T_planes, top_over_T_distance;
  double first_within_1pct_planes = 0.0, first_within_1pct_distance = 0.0;
  double first_within_10pct_planes = 0.0, first_within_10pct_distance = 0.0;
  double top_ge_90pct_planes = 0.0, top_ge_90pct_distance = 0.0;
  double complete_share = 0.0;
  double area_coverage = 0.0;
};

LayerFidelity measure_layer_fidelity(const VolumeMesh& mesh, const TriSurface& wall,
                                     const LayerFidelityTargets& targets);

// The mesh renumbered so that its points 0..V-1 are the wall's points, for meshes from
// other meshers, whose wall points are not first: each wall point is matched to the
// nearest mesh point within 1e-6 of the wall's bounding-box diagonal (another parser's
// reading of the same file differs by rounding) and takes the wall's coordinates. Other
// points follow in their original order; point arrays are dropped. Throws
// std::invalid_argument naming the first wall point that no mesh point matches.
VolumeMesh with_wall_points_first(const VolumeMesh& mesh, const TriSurface& wall);

// The summaries (not the per-column data) as a JSON object, keys as the member names
// with distributions nested: {"first_over_h1": {"planes": {"p50": ...}, "distance": ...},
// "first_within_1pct_planes": ..., ...}.
nlohmann::json layer_fidelity_to_json(const LayerFidelity& f);

}  // namespace blayer
