// The columns of an extrusion and the front they form: one column per wall point, or,
// at sharp convex edges (fan ridges), a fan of columns per point so that every face's
// layers leave the wall along the face's own normal.
//
// Ridges and fans
//   A wall edge is a fan ridge when it is convex and its dihedral turning angle (the
//   angle between the normals of its two triangles) exceeds fan_angle. A point on two
//   or more ridge edges, with a closed fan and not excluded, is a fan point; a ridge
//   edge needs at least one fan point (a ridge's free end, a boundary or excluded point
//   is a single column, and the ridge edge to it a ridge end).
//   A fan point's triangles split at its ridge edges into sectors; each sector gets a
//   column along the sector's own normal (normal_method on the sector's faces: for a
//   flat sector, the face normal). Across each ridge edge the directions between the two
//   sectors' normals are interpolated (slerp) so that no angular gap exceeds
//   max_sector: m - 1 sub-normal columns, m uniform over a ridge chain (ridge edges
//   joined through fan points on exactly two of them; corners and ridge ends separate
//   chains, since their fans across different edges are distinct). Turns within
//   kFanAngleSlack of fan_angle or of a multiple of max_sector count as those angles
//   (see there). A corner (three or
//   more ridge edges) also gets a centre column (the normalised sum of its loop's
//   directions), and its loop of directions is closed by a patch of triangles around it.
//
// The front (TriSurface `front`: one point per column, at the column's wall point)
//   - each wall triangle, on the columns of its sector at each of its points;
//   - per ridge edge (a, b), m quads (L_a[j], L_a[j+1], L_b[j+1], L_b[j]), L_x the fan
//     of x across the edge from the sector of the triangle that runs a -> b to the
//     other; each quad is also two front triangles (0,1,2), (0,2,3), for the checks;
//     at a ridge end (one of them a single column P) the quad is the triangle
//     (P, X, Y) of the fan's consecutive columns X, Y;
//   - per corner, the patch triangles (centre, loop[i], loop[i+1]), wound like the rest.
//   The front is closed and consistently oriented where the wall is. Strip and patch
//   triangles have zero area on the wall and open up as the columns grow.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/normals/point_normals.h"

namespace blayer {

struct FanParams {
  double fan_angle_deg = 60.0;    // 0 disables fans
  double max_sector_deg = 30.0;   // largest angle between neighbouring columns of a fan
};

// Fraction of an angle limit within which a wall angle counts as at the limit: a ridge
// turns by more than fan_angle x (1 + kFanAngleSlack), and its fans take
// m = ceil(turn / max_sector - kFanAngleSlack) slices. CAD edges turn by exact angles
// (a hexagon's 60 degrees, a box's 90: 3 slices of 30), and single-precision
// coordinates (every STL file) move a face normal by about 6e-8 times the
// coordinates' magnitude over the edge length: a 90-degree edge then reads 90.00001
// and took a fourth slice at random, chain by chain (a perforated block from STL had
// 2,513 more columns than from OFF and 4 fans that fell back), and a hexagon's edges
// became ridges at random. 1e-4 of 30 degrees is 0.003 degrees, far below any meaning
// for a fan, and above that noise on edges down to 1/900 of the coordinates' magnitude.
constexpr double kFanAngleSlack = 1e-4;

// What one layer of the front becomes: a triangle (a wall triangle's columns, or a
// corner patch triangle) or a strip quad (columns q0 q1 q2 q3, q0 q1 of one fan point
// and q2 q3 of the other, wound like the front). layer_cells.h turns it into cells.
//   kStripEnd: a strip slice where a ridge ends at a single column P: the front
//   triangle (P, X, Y), X and Y consecutive columns of the fan at the other end.
//   split_at: a wall triangle's corner (0..2) whose column ends a ridge: on the wall
//   layer its side faces there are split into triangles, like the strip ends beside it.
enum class ElementKind : std::uint8_t { kTriangle, kStrip, kStripEnd };
struct LayerElement {
  ElementKind kind = ElementKind::kTriangle;
  std::array<int, 4> column{-1, -1, -1, -1};  // kTriangle, kStripEnd: the first three
  int split_at = -1;

  int n_columns() const { return kind == ElementKind::kStrip ? 4 : 3; }
};

struct ColumnLayout {
  TriSurface front;                       // points: per column, its wall point's position
  std::vector<int> wall_point;            // per column
  std::vector<int> wall_face;             // per front triangle: its wall triangle, or -1
  std::vector<LayerElement> elements;     // wall triangles, then strips, then patches
  std::vector<int> element_of_triangle;   // per front triangle
  std::vector<Vec3> direction;            // per column: its wall direction for fan points (else zero)
  std::vector<char> in_fan;               // per column: a column of a fan point
  std::vector<char> faceless;             // per column: a sub-normal or centre column
  int n_fan_points = 0;
  int n_ridge_edges = 0;                  // ridge edges that got fans
  int n_corners = 0;
  int n_ridge_ends = 0;                   // ridge edges from a fan point to a single column

  int n_columns() const { return static_cast<int>(wall_point.size()); }
  bool has_fans() const { return n_fan_points > 0; }
};

// No wall edge joins two ridge-end points (their split faces would disagree): the fan
// points on ridges to such a pair fall back to single columns until none does.
// excluded: per wall point, no fan there (points on a symmetry plane, points whose fan
// did not grow in an earlier attempt). Boundary points never get fans. With
// p.fan_angle_deg == 0 (or no ridge) the layout is one column per wall point, column v
// at wall point v, and the front is the wall.
ColumnLayout single_column_layout(const TriSurface& wall);

ColumnLayout build_column_layout(const TriSurface& wall, const VertexFans& fans, const FanParams& p,
                                 NormalMethod method, const std::vector<char>& excluded);

}  // namespace blayer
