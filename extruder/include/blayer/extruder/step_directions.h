// Step directions on a front: the point normals of the front (recomputed on every layer
// with the chosen method), optionally smoothed without losing visibility, their
// visibility against the incident front faces, and the direction repair that turns
// columns of failing cells towards their neighbours.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/point_normals.h"
#include "blayer/normals/vertex_normal.h"

namespace blayer {

struct StepDirections {
  std::vector<Vec3> face_normal;   // unit normals of the front's triangles
  std::vector<Vec3> n;             // unit step direction per column
  std::vector<double> visibility;  // min over incident front faces of n.f
  std::vector<char> ok;            // a usable (visible, non-degenerate) direction exists
};

// Directions on `front` (the wall's triangles on the current column tops) for the
// columns with active set. A column is ok when its normal has a status other than
// kNoVisibleDirection, is finite and non-zero, and its visibility is >= min_visibility.
// Smoothing (normal_smoothing_iterations Jacobi passes): each ok direction is blended
// towards the normalised sum of its own and its ok neighbours' directions, fully, by a
// half or by a quarter, and the first blend whose visibility is not below the
// unsmoothed direction's (nor min_visibility) is kept; otherwise it stays.
// Prescribed directions (fan columns on the wall, fan_layout.h): columns with a
// non-zero n take it with the given visibility, ok when that is >= min_visibility, and
// are not smoothed; their neighbours smooth towards them like towards any other.
struct PrescribedDirections {
  std::vector<Vec3> n;
  std::vector<double> visibility;
};
//
// memo (optional): the fan normals of a run's earlier attempts on the wall
// (extrude_layers.cpp marches again after fan points fall back), by wall point. A point
// whose fan geometry (the point, its ring's points in order, and whether the ring
// closes) is bitwise the one stored takes the stored normal, a pure function of that
// geometry; the others are solved. Each call stores the fans of its points anew: every
// fan while the memo keeps the cheap ones, since the precheck rounds rebuild the whole
// layout around a few points that fell back and each round solved every wall normal
// again (on the ONERA M6 571k, half a second of the second round); a marching attempt
// keeps only the fans of at least kMemoMinValence triangles (drop_cheap): smaller ones
// solve in microseconds, and the memo would otherwise add to the march's memory. The
// entries lie in a few flat arrays, so that dropping them returns their memory.
constexpr std::size_t kMemoMinValence = 10;
struct WallNormalMemo {
  std::vector<int> wall_point;         // per entry, ascending
  std::vector<std::size_t> start;      // per entry, into points, with a final end
  std::vector<Vec3> points;            // per entry: the point, then its ring
  std::vector<char> closed;            // per entry
  std::vector<VertexNormal> normal;    // per entry
  long reused = 0;  // normals taken from the memo, over the run
  long solved = 0;  // fan normals solved while a memo was given
  // Whether fans of fewer than kMemoMinValence ring points (triangles, on a closed fan)
  // are stored.
  bool keep_cheap = true;
  // The entry of wall point w, or -1.
  int entry_of(int w) const;
  // Frees the entries of fans below kMemoMinValence triangles and stores no more of
  // them.
  void drop_cheap();
  bool stores(const VertexFan& fan) const { return keep_cheap || fan.ring.size() >= kMemoMinValence; }
};

// warm (optional): most-normal warm starts carried from front to front (most_normal.h),
// one per column, for the recomputed directions. A front differs little from the one
// below it, so a column's previous optimum, rebuilt from its generators on the new fan,
// bounds the search from the start. The normals are the cold solve's in status and D,
// and in direction outside the tie band, where a tighter bound can pick another
// maximiser of equal D.
// Only a visibility-constrained optimum is carried to the next front. There the bound
// prunes the constraint leaves, which are most of the solve: on the perforated CAD
// block the fronts' normals take about a sixth less time. On unconstrained fans the
// cold solve is as fast, and the warm one's choices inside the tie band moved mesh
// points of the 717 wing by up to 2e-8; carried only where constrained, the meshes of
// the benchmark surfaces are bitwise those of cold solves (docs/extrusion.md).
// counts sums, over the run, the solves that came with a valid warm start and those
// whose certificate held.
struct FrontWarmStarts {
  std::vector<MostNormalWarmStart> by_column;
  WarmStartCounts counts;
};

StepDirections compute_step_directions(const TriSurface& front, const WallTopology& topo,
                                       const std::vector<char>& active, const ExtrusionParams& p,
                                       const PrescribedDirections* prescribed = nullptr,
                                       WallNormalMemo* memo = nullptr, FrontWarmStarts* warm = nullptr);

// The point normal (normal_method) of surface s at point v alone, with topo =
// build_wall_topology(s); a point on the symmetry plane gets the normal of its fan
// mirrored about it, in the plane.
VertexNormal surface_point_normal(const TriSurface& s, const WallTopology& topo, int v, NormalMethod method);

// Directions for a later layer from the previous layer's (column_directions):
//   kKept        each column keeps its direction while it sees the current front's
//                faces by min_visibility, so columns stay straight where the front is
//                an offset of the wall; a column that does not is turned towards the
//                front's own point normal (normal_method, computed for that point only)
//                by the least blend that restores half of that normal's visibility
//                (or min_visibility, whichever is larger); it is not ok when even the
//                front normal is below min_visibility. *n_turned counts those columns.
//   kRecomputed  compute_step_directions on the front (normals recomputed everywhere),
//                warm-started from the previous front's when warm is given.
StepDirections update_step_directions(const TriSurface& front, const WallTopology& topo,
                                      const std::vector<char>& active, const ExtrusionParams& p,
                                      const StepDirections& previous, int* n_turned,
                                      FrontWarmStarts* warm = nullptr);

// min over the incident front faces of v of n.f.
double visibility_of(const StepDirections& d, const WallTopology& topo, int v, const Vec3& n);

// Direction repair: failing cells and colliding triangles mostly come from neighbouring
// columns that diverge sideways by more than a short edge (thin triangles, mild
// concavity). Each column with bad set is turned towards the normalised sum of the
// directions of the growing columns of its failing triangles (bad_triangle), when that
// direction keeps at least half of the column's visibility and min_visibility. Returns
// per column whether it was turned (d->n and d->visibility updated for those).
std::vector<char> turn_failing_columns(const std::vector<Triangle>& triangles, const WallTopology& topo,
                                       const std::vector<char>& bad, const std::vector<char>& bad_triangle,
                                       const std::vector<char>& grows, double min_visibility, StepDirections* d);

}  // namespace blayer
