// Extrusion of a wall renumbered in a spatial order, with the wall's own numbering given
// back to the result.
//
// Why: the marching's trees visit the triangles of one region together and read their
// columns' points, and the assembly and the check read the cells of a region together.
// Numbered as a CAD export lists them (patch by patch, in no spatial order), these
// reads miss the cache; numbered along a space-filling curve (core/spatial_order.h)
// they do not. The whole `blayer extrude` run took 6-13 % less wall time on the
// perforated block of bench/make_perforated_block.py, 15-18 % less on the ONERA M6 16k
// and 29 % less on the M6 571k, for the same meshes.
//
// What the result keeps and what changes, against extrude_layers on the wall as given:
//   kept: the wall points' indices 0..V-1 in the mesh (the extruder's contract) with
//     their rows of the point arrays (for fan points see below), the envelope's first F triangles (F = the wall's triangle count)
//     above wall triangles 0..F-1 in that order, and every id of a wall point or wall
//     triangle in the result (column_wall_point, front_wall_face, envelope_point_ids);
//   restored: the columns' order, by wall point in the wall's order (one column per
//     point: column v at wall point v, as extrude_layers numbers them; a fan point's
//     columns together, its sub-normal and centre columns among them);
//   changed: the numbering of the layer points and of the cells within each layer,
//     which follow the spatial order; the node order of fan cells (strips, corner
//     patches), whose first node follows the order in which the wall lists its
//     triangles, and with it the check's growth ratio of the strip-end wedges that lie
//     along a ridge (their caps face along it, so their "cell above" is a neighbour
//     along the ridge, at one end or the other); which of a fan point's columns its
//     wall row of the point arrays shows
//     (the first in column order); and floating-point sums over a point's neighbours,
//     taken in another order, which move points by rounding (by at most 2e-15 on the
//     perforated block, in coordinates up to 5; 8e-13 on the ONERA M6 half model, in
//     coordinates up to 1.2, accumulated over ten layers).
//   The march decides the same (which columns stop, where and why) in any numbering,
//   up to such rounding: input_order_test.cpp pins this on shuffled walls.
#pragma once

#include <functional>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/extruder/extrusion_params.h"

namespace blayer {

struct WallRenumbering {
  std::vector<int> point_source;     // renumbered point i is the wall's point point_source[i]
  std::vector<int> triangle_source;  // renumbered triangle j is the wall's triangle triangle_source[j]
  bool keeps_input_order = false;    // the identity: the wall's own order was as good
  // How far apart each numbering puts neighbours: the mean, over the pairs of triangles
  // sharing an edge, of log2(1 + the difference of their positions).
  double input_spread_bits = 0.0;
  double spatial_spread_bits = 0.0;
};

// A spatial order must bring neighbours this many bits closer (2^1: twice, in the
// geometric mean) to replace the wall's own. Structured surface grids (pyHyp's wings,
// 3.2 bits) and strip-wise CAD tessellations (the sliver wing segment of
// bench/make_sliver_wing.py, 5.5 bits) come numbered along the surface, better than
// the curve does it (4.5 and 10.3 bits): in their spatial order the run took 1-6 % more
// time. The perforated block (8.5 bits against 3.1) and the ONERA M6 (9.5 against 2.8)
// took 6-13 % and 15-29 % less.
constexpr double kMinSpreadGainBits = 1.0;

// Points along the Morton curve of their positions, triangles along that of their
// centroids, where that gains kMinSpreadGainBits on the wall's own order; else the
// identity (keeps_input_order). Corners keep their order within each triangle (the
// winding is kept).
WallRenumbering spatial_renumbering(const TriSurface& wall);

// The wall in the renumbering: point i = wall point point_source[i], triangle j = wall
// triangle triangle_source[j] on the new point indices.
TriSurface renumbered_wall(const TriSurface& wall, const WallRenumbering& r);

// The inverse: the wall as given, from its renumbering.
TriSurface wall_in_input_order(const TriSurface& renumbered, const WallRenumbering& r);

// Gives a result extruded from renumbered_wall(wall, r) the wall's own numbering, as
// listed under "kept" above. Precondition (BLAYER_ASSERT): the result's mesh starts
// with the wall's points and its envelope with the wall's triangles, in order.
void restore_wall_numbering(const WallRenumbering& r, ExtrusionResult* result);

// extrude_layers on the wall renumbered by spatial_renumbering, the result restored
// (extrude_layers itself where the renumbering keeps the input order). The wall is
// renumbered in place for the march (a copy would add to the peak memory)
// and given back in its own numbering, also when extrude_layers throws.
ExtrusionResult extrude_layers_in_spatial_order(TriSurface* wall, const ExtrusionParams& params,
                                                const std::function<void(int layer, int n_layers)>& progress = {});

}  // namespace blayer
