// Whole-mesh check of a VolumeMesh: exact validity of every cell, face conformity,
// per-cell metrics and their summaries, as used by `blayer check` and by the extruder's
// run report. The family is kept in one header because its functions share the report
// type; each has its own source file.
//
// What is checked
//   validity     cell_validity() per cell (exact orient3d; see cell_validity.h):
//                inverted (a negative corner Jacobian), flat (a zero one) and twisted
//                (every corner positive, some split tet not) are counted apart; each of
//                them fails the check.
//   metrics      compute_cell_metrics() per cell (see cell_metrics.h), plus the volume
//                growth ratio of a column: volume of the cell across the top cap divided
//                by the cell's volume.
//   faces        faces are matched by node set. Detected, exactly (topology only):
//     - a face shared by more than two cells ("overshared");
//     - a face shared by two cells that traverse it in the same direction, i.e. both
//       cells lie on the same side of it ("misoriented": an overlap or a fold);
//     - non-conforming faces: two faces with the same node set but a different cyclic
//       order (a quad matched by a crossed quad), and any triangle face whose three
//       nodes are a subset of an unmatched quad face of another cell (a quad face
//       matched by two triangles, or by one triangle and a gap).
//   Not detected: hanging nodes that lie geometrically on an edge or face of a
//   neighbour without being one of its nodes (T-junctions); that needs geometric
//   tolerances, and the matching is purely topological so it never misfires.
//   Unmatched faces that are not in a subset relation count as boundary faces.
//
// Threads: the per-cell passes and the face matching run in parallel with TBB (use
// tbb::global_control to limit them). The result does not depend on the thread count.
// Memory: about 8 bytes per cell face plus the per-cell arrays of the report (66
// bytes per cell).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blayer/core/volume_mesh.h"
#include "blayer/quality/cell_validity.h"

namespace blayer {

// Per-cell problem bits (MeshCheckReport::flags, and the `check_flags` cell array).
enum class CellCheckFlag : std::uint8_t {
  kFlat = 1,               // validity == kFlat
  kInverted = 2,           // validity == kInverted
  kNonConforming = 4,      // has a non-conforming face (see above)
  kOversharedFace = 8,     // has a face shared by more than two cells
  kMisorientedFace = 16,   // shares a face with a cell on the same side of it
  kNonFinite = 32,         // a corner coordinate is NaN or infinite (also kInverted)
  kTwisted = 64,           // validity == kTwisted
};

inline bool has_flag(std::uint8_t flags, CellCheckFlag f) {
  return (flags & static_cast<std::uint8_t>(f)) != 0;
}

// Distribution of one metric over the cells where it is defined (finite values only;
// NaN, e.g. orthogonality of a tet or growth of a column's last cell, is skipped).
// Percentiles use the nearest rank: p_q = sorted[floor(q * (count - 1))]. All NaN when
// count == 0.
struct MetricSummary {
  std::string name;
  std::size_t count = 0;
  double min = 0, p1 = 0, p5 = 0, p50 = 0, p95 = 0, p99 = 0, max = 0;
};

// Counts and summaries of a subset of cells (the whole mesh, or one layer).
struct CheckCounts {
  std::array<std::size_t, 4> by_type{};  // indexed by check_type_index(): tet, pyramid, wedge, hex
  std::size_t cells = 0;
  std::size_t inverted = 0;              // validity kInverted: a negative corner Jacobian
  std::size_t twisted = 0;               // validity kTwisted: corners positive, a split tet not
  std::size_t flat = 0;
  std::size_t non_conforming = 0;        // cells with kNonConforming
  std::vector<MetricSummary> metrics;    // in the order of kCheckMetricNames
};

struct LayerCheck {
  long layer = 0;  // value of the `layer` cell array
  CheckCounts counts;
};

// Names of the per-cell metrics, in the order of MeshCheckReport::metrics and of
// CheckCounts::metrics; they are also the cell-array names of add_quality_arrays().
inline constexpr std::array<const char*, 7> kCheckMetricNames = {
    "min_corner_jacobian", "skewness", "aspect_ratio", "orthogonality_deg",
    "twist", "growth_ratio", "volume"};
// The signed cell volume's place among them.
inline constexpr std::size_t kVolumeMetric = 6;

struct MeshCheckReport {
  std::size_t n_points = 0;
  CheckCounts totals;

  // Face matching, counted once per distinct face (node set).
  std::size_t boundary_faces = 0;         // unmatched and not in a subset relation
  std::size_t non_conforming_faces = 0;   // faces taking part in a non-conformity
  std::size_t overshared_faces = 0;       // faces with more than two cells
  std::size_t misoriented_faces = 0;      // two cells on the same side

  // Per cell, n_cells entries each.
  std::vector<Validity> validity;
  std::vector<std::uint8_t> flags;                  // CellCheckFlag bits
  std::vector<std::int64_t> upper_neighbour;        // cell across the top cap, or -1
  std::array<std::vector<double>, 7> metrics;       // by kCheckMetricNames

  // One entry per distinct value of a 1-component `layer` cell array, ascending;
  // empty when the mesh has no such array.
  std::vector<LayerCheck> layers;

  double min_scaled_jacobian() const { return totals.metrics.empty() ? 0.0 : totals.metrics[0].min; }
  // No inverted, twisted, flat, non-conforming, overshared or misoriented cell.
  bool ok() const;
  // A cell fails when any flag is set.
  bool cell_fails(std::size_t c) const { return flags[c] != 0; }
};

// 0 tet, 1 pyramid, 2 wedge, 3 hex.
int check_type_index(CellType t);

// How much of the metrics check_volume_mesh summarises. The per-cell results (validity,
// flags, metrics) and the counts are the same either way.
//   kFull     min, percentiles and max of every metric over the mesh and over each layer
//   kMinMax   min and max over the mesh only: the percentiles NaN, no layers. For a
//             caller that shows no table (extrude without --report): the selections took
//             a fifth of the check of the perforated block's 528k cells.
enum class CheckSummaries { kFull, kMinMax };

// Checks every cell and face. Throws InputError when the mesh structure is unusable
// (offsets and types disagree, a cell has the wrong node count, a node index is out of
// range); bad geometry is reported, never thrown.
MeshCheckReport check_volume_mesh(const VolumeMesh& mesh, CheckSummaries summaries = CheckSummaries::kFull);

// Human-readable multi-line summary: counts by cell type, inverted/twisted/flat/non-conforming
// and face counts, a table of min and percentiles per metric, then the same per layer.
std::string format_check_report(const MeshCheckReport& report);

// JSON object with keys:
//   ok (bool), n_cells, n_points,
//   cells {tet, pyramid, wedge, hex} (counts),
//   inverted, twisted, flat, non_conforming (cell counts; inverted counts only the
//   cells with a negative corner Jacobian, as VTK, Gmsh and ParaView do),
//   non_conforming_faces, overshared_faces, misoriented_faces, boundary_faces,
//   min_scaled_jacobian (number, null if no cell),
//   metrics {<name>: {count, min, p1, p5, p50, p95, p99, max}} (null for NaN),
//   layers [{layer, cells, inverted, twisted, flat, non_conforming, metrics {...}}] (only when
//   the mesh has a `layer` array).
nlohmann::json check_report_to_json(const MeshCheckReport& report);

// The failing cells (report.cell_fails) as a standalone mesh: only the points they use
// (renumbered), their original cell arrays and point arrays, the quality arrays of
// add_quality_arrays() and `original_cell_id` (int). report must come from this mesh.
VolumeMesh extract_bad_cells(const VolumeMesh& mesh, const MeshCheckReport& report);

// Adds (or replaces) per-cell arrays for thresholding in ParaView:
//   min_corner_jacobian  double  scaled Jacobian (CellMetrics::scaled_jacobian), 1 ideal
//   skewness             double  equiangle skew of the caps (wedge) or all faces, [0,1]
//   aspect_ratio         double  cap size / column height (wedge, hex); edge ratio otherwise
//   orthogonality_deg    double  worst column-edge to cap-normal angle, deg; NaN tet/pyramid
//   twist                double  worst quad-face warp angle, deg; 0 with no quads
//   growth_ratio         double  volume of the cell across the top cap / own volume; NaN if none
//   volume               double  signed volume
//   validity             int     0 valid, 1 flat, 2 inverted, 3 twisted (exact)
//   check_flags          int     CellCheckFlag bits (1 flat, 2 inverted, 4 non-conforming,
//                                8 overshared face, 16 misoriented face, 32 non-finite,
//                                64 twisted)
// The first overload runs check_volume_mesh(); the second reuses a report of this mesh.
void add_quality_arrays(VolumeMesh& mesh);
void add_quality_arrays(VolumeMesh& mesh, const MeshCheckReport& report);
// The same arrays, the metrics moved out of *report instead of copied (a report of
// millions of cells holds hundreds of MB of them): afterwards report->metrics are
// empty; its totals, layers, validity and flags stay.
void move_quality_arrays(VolumeMesh& mesh, MeshCheckReport* report);

}  // namespace blayer
