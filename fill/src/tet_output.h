// TetGen's result brought back to the caller's numbering and checked against the
// contract of tet_fill.h ("Output checks"); every failure is an InputError.
#pragma once

#include "blayer/fill/tet_fill.h"
#include "tet_plc.h"
#include "tetgen_adapter.h"

namespace blayer::fill_detail {

// result->tets: envelope points, farfield points, then Steiner points; tets with
// positive volume. result->boundary and boundary_marker: envelope then farfield
// triangles on those points. Checks that TetGen returned the input points unchanged
// and first, and only valid point indices.
void assemble_fill_result(const TriSurface& envelope, const OuterBoundary& outer, const FillPlc& plc,
                          const TetgenMesh& mesh, FillResult* result);

// The faces used by exactly one tet are exactly the boundary triangles, no face is
// shared by more than two tets, and the tet on each boundary triangle lies on the side
// its normal points to.
void check_conformity(const FillResult& result);

// Tet counts, dihedral angles, radius-edge ratios and volumes into result->stats.
void add_quality_stats(FillResult* result);

}  // namespace blayer::fill_detail
