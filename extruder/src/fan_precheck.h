// The straight-layer precheck of fan points (extrude_layers): before marching, the
// first layer of the fan cells (strips, strip ends, corner patches, the triangles split
// at ridge ends and the wall triangles on fan columns) is built on straight columns at
// its planned height and tested exactly. The fan points of a failing cell fall back to
// one column, and the layout is rebuilt. Cells that fold higher up are left to the march,
// which lowers or stops their columns there (fan_precheck.cpp says why).
//
// Rounds: each rebuilt layout is checked again, and most of its fan elements are the
// previous round's, on columns through the same points. The validity test is a pure
// function of a cell's corners, so an element whose columns all run through bitwise the
// same points as an element that passed in the previous round (same kind,
// same split, the same columns in the same order) passes again without being rebuilt:
// the failing set is the one a full check finds. Only a failing round is followed by
// another, so only a failing round keeps its records for the next. Internal to
// blayer_extruder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_planes.h"

namespace blayer {

class FanPrecheck {
 public:
  // The wall points (ascending) of the fan points of `layout` whose first-layer cells
  // fail on straight columns along dirs at plan's first height, each column's step
  // stretched to its height above the wall planes (capped at params.max_step_stretch).
  // last_round: the caller needs only to know whether any fan point fails (all of them
  // fall back then): the round keeps no records.
  std::vector<int> failing_points(const TriSurface& wall, const ColumnLayout& layout, const WallPlanes& planes,
                                  const StepDirections& dirs, const ColumnPlan& plan, const ExtrusionParams& params,
                                  bool last_round = false);
  // Frees the previous round's records (once the fans passed, before marching).
  void release();
  // Elements of the last round that passed as the previous round's (diagnostics, tests).
  std::size_t reused_elements() const { return reused_; }

 private:
  struct ElementKey {
    int kind = 0, split_at = -1;
    int runs[4] = {-1, -1, -1, -1};  // the columns' trajectory ids, in element order
    bool operator<(const ElementKey& o) const;
  };
  // One round's straight columns and the elements that passed. A column's trajectory
  // (its id is the column) is its run through the prechecked layer, as bits: its wall
  // point, whether it grows that layer (not without a direction) and then the top,
  // its step stretched to its height above the wall planes (capped at
  // params.max_step_stretch).
  struct Round {
    std::vector<std::uint64_t> runs;                        // the trajectories, concatenated
    std::vector<std::size_t> run_start;                     // per column, with a final end
    std::vector<std::pair<std::uint64_t, int>> by_hash;     // (hash, column) of the followed ones, sorted once kept
    std::vector<ElementKey> passed;                         // sorted
    // A column of this round with trajectory [t, t + n), or -1.
    int find(const std::uint64_t* t, std::size_t n, std::uint64_t hash) const;
    bool grows(int c) const;
    Vec3 top(int c) const;  // of a column that grows
  };
  // The trajectories of the columns with `needed` set; the others have empty runs and
  // no hash.
  static Round round_of(const TriSurface& wall, const ColumnLayout& layout, const WallPlanes& planes,
                        const StepDirections& dirs, const ColumnPlan& plan, const ExtrusionParams& params,
                        const std::vector<char>& needed);
  // The element's key with its columns' trajectory ids: (*run)[c], or the columns
  // themselves (this round's ids) when run is null.
  static ElementKey key_of(const LayerElement& e, const std::vector<int>* run);
  // Per checked element: 1 if it passed in the previous round on the same trajectories.
  std::vector<signed char> passed_before(const ColumnLayout& layout, const std::vector<std::size_t>& checked,
                                         const Round& current) const;

  Round previous_;
  std::size_t reused_ = 0;
};

}  // namespace blayer
