#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "blayer/core/cyclic_index.h"
#include "blayer/core/errors.h"
#include "blayer/quality/cell_metrics.h"
#include "blayer/quality/mesh_check.h"
#include "cell_faces.h"

namespace blayer {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

constexpr std::uint8_t bit(CellCheckFlag f) { return static_cast<std::uint8_t>(f); }

// What is wrong with cell c's type, node count or node ids; empty when nothing is.
std::string cell_structure_error(const VolumeMesh& mesh, std::size_t c) {
  const auto n_points = static_cast<std::int64_t>(mesh.points.size());
  const int k = corner_count(mesh.cell_types[c]);
  if (k == 0) return "check_volume_mesh: cell " + std::to_string(c) + " has an unsupported type";
  if (mesh.offsets[c + 1] - mesh.offsets[c] != k)
    return "check_volume_mesh: cell " + std::to_string(c) + " (" + cell_type_name(mesh.cell_types[c]) + ") has " +
           std::to_string(mesh.offsets[c + 1] - mesh.offsets[c]) + " nodes, expected " + std::to_string(k);
  for (std::int64_t i = mesh.offsets[c]; i < mesh.offsets[c + 1]; ++i)
    if (mesh.connectivity[i] < 0 || mesh.connectivity[i] >= n_points)
      return "check_volume_mesh: cell " + std::to_string(c) + " uses node " + std::to_string(mesh.connectivity[i]) +
             ", outside [0, " + std::to_string(n_points) + ")";
  return {};
}

void check_structure(const VolumeMesh& mesh) {
  const std::size_t n = mesh.n_cells();
  if (mesh.offsets.size() != n + 1 || mesh.offsets.front() != 0)
    throw InputError("check_volume_mesh: offsets has " + std::to_string(mesh.offsets.size()) +
                     " entries for " + std::to_string(n) + " cells (expected n_cells + 1, starting at 0)");
  if (mesh.offsets.back() != static_cast<std::int64_t>(mesh.connectivity.size()))
    throw InputError("check_volume_mesh: last offset " + std::to_string(mesh.offsets.back()) +
                     " differs from the connectivity size " + std::to_string(mesh.connectivity.size()));
  // The cells are scanned in parallel (serially, 10 ms of a 528k-cell check) for the
  // first ill-formed one.
  const std::size_t first_bad = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n), n,
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t found) {
        for (std::size_t c = r.begin(); c < r.end() && c < found; ++c)
          if (!cell_structure_error(mesh, c).empty()) return c;
        return found;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (first_bad < n) throw InputError(cell_structure_error(mesh, first_bad));
}

// A face of a cell as integers that compare in one or two instructions. A face is
// filed in the bucket of its smallest node id m (bucket_faces), so its keys hold the
// ids after m, each padded to three with kNoId and packed two to a word (ids are
// non-negative 32-bit values, check_structure, so a packed pair compares as the pair
// does): `sorted` the node set, with the node count; `cyclic` the ids around the face
// from m, in the direction whose next id is the smaller (for a quad the opposite node
// is then third: a crossed quad on the same nodes differs there); `reversed` whether
// that direction runs against the face's winding. Where m occurs twice in a degenerate
// face, its first place starts both readings.
constexpr std::uint32_t kNoId = 0xffffffffu;

struct FaceEntry {
  std::array<std::uint64_t, 2> sorted;
  std::array<std::uint64_t, 2> cyclic;
  std::int64_t cell;
  std::uint8_t face;
  bool reversed;
  int node_count() const { return static_cast<int>(sorted[1] >> 32); }
};

std::array<std::uint64_t, 2> pack_ids(const std::uint32_t* ids, int n) {
  return {std::uint64_t{ids[0]} << 32 | ids[1], std::uint64_t(n) << 32 | ids[2]};
}

FaceEntry face_entry(const VolumeMesh& mesh, std::int64_t cell, int face) {
  const detail::FaceDef& fd = detail::cell_faces(mesh.cell_types[cell]).faces[face];
  const PointId* nodes = mesh.cell_nodes(cell);
  const int n = fd.n;
  std::uint32_t v[4];
  int lo = 0;
  for (int i = 0; i < n; ++i) {
    v[i] = static_cast<std::uint32_t>(nodes[fd.v[i]]);
    if (v[i] < v[lo]) lo = i;
  }
  std::uint32_t fwd[3] = {kNoId, kNoId, kNoId}, bwd[3] = {kNoId, kNoId, kNoId};
  for (int i = 1; i < n; ++i) {
    fwd[i - 1] = v[cyclic_wrap(lo + i, n)];
    bwd[i - 1] = v[cyclic_wrap(lo - i, n)];
  }
  FaceEntry e;
  e.cell = cell;
  e.face = static_cast<std::uint8_t>(face);
  const std::array<std::uint64_t, 2> f = pack_ids(fwd, n), b = pack_ids(bwd, n);
  e.reversed = b < f;
  e.cyclic = e.reversed ? b : f;
  // Sorting network of three (the padding, the largest value, stays last).
  if (fwd[1] < fwd[0]) std::swap(fwd[0], fwd[1]);
  if (fwd[2] < fwd[1]) std::swap(fwd[1], fwd[2]);
  if (fwd[1] < fwd[0]) std::swap(fwd[0], fwd[1]);
  e.sorted = pack_ids(fwd, n);
  return e;
}

struct FaceCounters {
  std::size_t boundary = 0, non_conforming = 0, overshared = 0, misoriented = 0;
};

// Faces bucketed by their smallest node (CSR): bucket m holds records cell * 8 + face.
struct FaceBuckets {
  std::vector<std::int64_t> start;
  std::vector<std::uint64_t> records;
};

FaceBuckets bucket_faces(const VolumeMesh& mesh) {
  const std::size_t n_points = mesh.points.size();
  const std::size_t n_cells = mesh.n_cells();
  std::unique_ptr<std::atomic<std::uint32_t>[]> count(new std::atomic<std::uint32_t>[n_points]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_points), [&](const auto& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) count[i].store(0, std::memory_order_relaxed);
  });
  auto for_each_face = [&](auto&& fn) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_cells), [&](const auto& r) {
      for (std::size_t c = r.begin(); c < r.end(); ++c) {
        const detail::CellFaces& cf = detail::cell_faces(mesh.cell_types[c]);
        const PointId* nodes = mesh.cell_nodes(c);
        for (int f = 0; f < cf.n_faces; ++f) {
          std::int64_t m = nodes[cf.faces[f].v[0]];
          for (int i = 1; i < cf.faces[f].n; ++i) m = std::min<std::int64_t>(m, nodes[cf.faces[f].v[i]]);
          fn(c, f, m);
        }
      }
    });
  };
  for_each_face([&](std::size_t, int, std::int64_t m) { count[m].fetch_add(1, std::memory_order_relaxed); });
  FaceBuckets b;
  b.start.assign(n_points + 1, 0);
  for (std::size_t i = 0; i < n_points; ++i) {
    b.start[i + 1] = b.start[i] + count[i].load(std::memory_order_relaxed);
    count[i].store(0, std::memory_order_relaxed);
  }
  b.records.resize(static_cast<std::size_t>(b.start[n_points]));
  for_each_face([&](std::size_t c, int f, std::int64_t m) {
    const std::uint32_t slot = count[m].fetch_add(1, std::memory_order_relaxed);
    b.records[b.start[m] + slot] = static_cast<std::uint64_t>(c) * 8 + static_cast<std::uint64_t>(f);
  });
  return b;
}

bool same_face(const FaceEntry& a, const FaceEntry& b) { return a.sorted == b.sorted; }

// Face matching: fills flags (atomic bit-or), upper_neighbour and the counters.
void match_faces(const VolumeMesh& mesh, std::atomic<std::uint8_t>* flags, std::vector<std::int64_t>& upper,
                 FaceCounters* totals) {
  const FaceBuckets b = bucket_faces(mesh);
  const std::size_t n_points = mesh.points.size();
  tbb::combinable<FaceCounters> counters;
  auto mark = [&](std::int64_t cell, CellCheckFlag f) { flags[cell].fetch_or(bit(f), std::memory_order_relaxed); };

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_points, 1024), [&](const auto& r) {
    FaceCounters& fc = counters.local();
    std::vector<FaceEntry> entries;
    for (std::size_t m = r.begin(); m < r.end(); ++m) {
      entries.clear();
      for (std::int64_t i = b.start[m]; i < b.start[m + 1]; ++i)
        entries.push_back(face_entry(mesh, static_cast<std::int64_t>(b.records[i] / 8), static_cast<int>(b.records[i] % 8)));
      // Equal node sets become neighbours. What follows depends only on the groups, not
      // on the order within or between them: counts add up, flags are or-ed, and each
      // cell's top cap lies in one group.
      std::sort(entries.begin(), entries.end(),
                [](const FaceEntry& x, const FaceEntry& y) { return x.sorted < y.sorted; });
      for (std::size_t g = 0; g < entries.size();) {
        std::size_t e = g + 1;
        while (e < entries.size() && same_face(entries[g], entries[e])) ++e;
        const std::size_t size = e - g;
        bool same_cyclic = true;
        for (std::size_t i = g + 1; i < e; ++i) same_cyclic = same_cyclic && entries[i].cyclic == entries[g].cyclic;
        if (!same_cyclic) {
          ++fc.non_conforming;
          for (std::size_t i = g; i < e; ++i) mark(entries[i].cell, CellCheckFlag::kNonConforming);
        } else if (size > 2) {
          ++fc.overshared;
          for (std::size_t i = g; i < e; ++i) mark(entries[i].cell, CellCheckFlag::kOversharedFace);
        } else if (size == 2) {
          const FaceEntry& x = entries[g];
          const FaceEntry& y = entries[g + 1];
          if (x.reversed == y.reversed) {
            ++fc.misoriented;
            mark(x.cell, CellCheckFlag::kMisorientedFace);
            mark(y.cell, CellCheckFlag::kMisorientedFace);
          } else {
            const detail::CellFaces& cx = detail::cell_faces(mesh.cell_types[x.cell]);
            const detail::CellFaces& cy = detail::cell_faces(mesh.cell_types[y.cell]);
            if (x.face == cx.top_cap && y.face == cy.bottom_cap) upper[x.cell] = y.cell;
            if (y.face == cy.top_cap && x.face == cx.bottom_cap) upper[y.cell] = x.cell;
          }
        } else if (entries[g].node_count() == 4) {
          // An unmatched quad: look for triangles on three of its nodes in the buckets
          // of those triangles' smallest nodes. The quad's nodes are m and, ascending,
          // rest[0..2]; without m the smallest is rest[0].
          const FaceEntry& q = entries[g];
          const std::uint32_t rest[3] = {static_cast<std::uint32_t>(q.sorted[0] >> 32),
                                         static_cast<std::uint32_t>(q.sorted[0]), static_cast<std::uint32_t>(q.sorted[1])};
          std::size_t found = 0;
          for (int skip = -1; skip < 3; ++skip) {
            // The triangle's ids other than m (skip < 0: all three, m skipped), padded;
            // without m its bucket is its smallest id, and its key holds the other two.
            std::uint32_t tri[4] = {kNoId, kNoId, kNoId, kNoId};
            for (int i = 0, j = 0; i < 3; ++i)
              if (i != skip) tri[j++] = rest[i];
            const std::size_t tm = skip < 0 ? tri[0] : m;
            const std::array<std::uint64_t, 2> want = pack_ids(skip < 0 ? tri + 1 : tri, 3);
            for (std::int64_t i = b.start[tm]; i < b.start[tm + 1]; ++i) {
              const auto cell = static_cast<std::int64_t>(b.records[i] / 8);
              const int face = static_cast<int>(b.records[i] % 8);
              if (cell == q.cell || detail::cell_faces(mesh.cell_types[cell]).faces[face].n != 3) continue;
              if (face_entry(mesh, cell, face).sorted != want) continue;
              ++found;
              mark(cell, CellCheckFlag::kNonConforming);
            }
          }
          if (found > 0) {
            mark(q.cell, CellCheckFlag::kNonConforming);
            fc.non_conforming += 1 + found;
          } else {
            ++fc.boundary;
          }
        } else {
          ++fc.boundary;
        }
        g = e;
      }
    }
  });
  counters.combine_each([&](const FaceCounters& c) {
    totals->boundary += c.boundary;
    totals->non_conforming += c.non_conforming;
    totals->overshared += c.overshared;
    totals->misoriented += c.misoriented;
  });
}

MetricSummary summarize(const char* name, std::vector<double> v, bool percentiles) {
  MetricSummary s;
  s.name = name;
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  s.count = v.size();
  s.min = s.p1 = s.p5 = s.p50 = s.p95 = s.p99 = s.max = kNaN;
  if (v.empty()) return s;
  if (!percentiles) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    s.min = *lo;
    s.max = *hi;
    return s;
  }
  // Nearest-rank percentiles by successive selection on the shrinking upper part: O(n),
  // where a full sort of millions of values dominated the whole check.
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  s.min = *lo;
  s.max = *hi;
  const double qs[5] = {0.01, 0.05, 0.50, 0.95, 0.99};
  double* out[5] = {&s.p1, &s.p5, &s.p50, &s.p95, &s.p99};
  auto first = v.begin();
  for (int i = 0; i < 5; ++i) {
    const auto k = v.begin() + static_cast<std::ptrdiff_t>(std::floor(qs[i] * static_cast<double>(v.size() - 1)));
    std::nth_element(first, k, v.end());
    *out[i] = *k;
    first = k;
  }
  return s;
}

// Counts and metric summaries over the n given cells (all cells when `cells` is null).
template <class Id>
CheckCounts count_cells(const VolumeMesh& mesh, const MeshCheckReport& r, const Id* cells, std::size_t n,
                        bool percentiles = true) {
  CheckCounts cc;
  auto id = [&](std::size_t i) { return cells ? static_cast<std::size_t>(cells[i]) : i; };
  cc.cells = n;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = id(i);
    ++cc.by_type[check_type_index(mesh.cell_types[c])];
    if (r.validity[c] == Validity::kInverted) ++cc.inverted;
    if (r.validity[c] == Validity::kTwisted) ++cc.twisted;
    if (r.validity[c] == Validity::kFlat) ++cc.flat;
    if (has_flag(r.flags[c], CellCheckFlag::kNonConforming)) ++cc.non_conforming;
  }
  cc.metrics.resize(kCheckMetricNames.size());
  tbb::parallel_for(std::size_t{0}, kCheckMetricNames.size(), [&](std::size_t k) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = r.metrics[k][id(i)];
    cc.metrics[k] = summarize(kCheckMetricNames[k], std::move(v), percentiles);
  });
  return cc;
}

// The counts of each value of the `layer` array, ascending. The cells are grouped by
// layer in one list of exact size (a counting sort, on 32-bit ids where they fit): a
// list per layer grown cell by cell held up to twice the ids, in the check's peak.
template <class Id>
void count_layers(const VolumeMesh& mesh, const DataArray& layer, MeshCheckReport* r) {
  const std::size_t n = mesh.n_cells();
  std::map<long, std::size_t> start;  // cells per layer, then where each layer's cells start
  for (std::size_t c = 0; c < n; ++c)
    if (std::isfinite(layer.values[c])) ++start[std::lround(layer.values[c])];
  std::size_t total = 0;
  for (auto& [value, count] : start) total += std::exchange(count, total);
  std::vector<Id> grouped(total);
  std::map<long, std::size_t> end = start;
  for (std::size_t c = 0; c < n; ++c)
    if (std::isfinite(layer.values[c])) grouped[end[std::lround(layer.values[c])]++] = static_cast<Id>(c);
  for (const auto& [value, first] : start)
    r->layers.push_back({value, count_cells(mesh, *r, grouped.data() + first, end[value] - first)});
}

}  // namespace

int check_type_index(CellType t) {
  switch (t) {
    case CellType::kTet: return 0;
    case CellType::kPyramid: return 1;
    case CellType::kWedge: return 2;
    case CellType::kHex: return 3;
  }
  return 0;
}

bool MeshCheckReport::ok() const {
  return totals.inverted == 0 && totals.twisted == 0 && totals.flat == 0 && totals.non_conforming == 0 &&
         overshared_faces == 0 &&
         misoriented_faces == 0;
}

MeshCheckReport check_volume_mesh(const VolumeMesh& mesh, CheckSummaries summaries) {
  check_structure(mesh);
  const std::size_t n = mesh.n_cells();
  MeshCheckReport r;
  r.n_points = mesh.points.size();
  r.upper_neighbour.assign(n, -1);

  // Faces first: their buckets (about 48 bytes per cell) are freed before the per-cell
  // metrics (56 bytes per cell) are allocated, so the two never add up in the peak.
  std::unique_ptr<std::atomic<std::uint8_t>[]> face_flags(new std::atomic<std::uint8_t>[n]);
  for (std::size_t c = 0; c < n; ++c) face_flags[c].store(0, std::memory_order_relaxed);
  FaceCounters fc;
  match_faces(mesh, face_flags.get(), r.upper_neighbour, &fc);
  r.boundary_faces = fc.boundary;
  r.non_conforming_faces = fc.non_conforming;
  r.overshared_faces = fc.overshared;
  r.misoriented_faces = fc.misoriented;

  // Allocated here, filled side by side: writing fresh memory (its page faults) is most
  // of their cost, which was 21 ms of the perforated block's check when filled in turn.
  r.validity.reserve(n);
  r.flags.reserve(n);
  for (std::vector<double>& m : r.metrics) m.reserve(n);
  tbb::parallel_for(std::size_t{0}, r.metrics.size() + 2, [&](std::size_t i) {
    if (i < r.metrics.size())
      r.metrics[i].assign(n, kNaN);
    else if (i == r.metrics.size())
      r.validity.assign(n, Validity::kValid);
    else
      r.flags.assign(n, 0);
  });
  enum { kJac, kSkew, kAspect, kOrtho, kTwist, kGrowth, kVolume };
  static_assert(kVolume == kVolumeMetric);

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
    Vec3 p[8];
    for (std::size_t c = range.begin(); c < range.end(); ++c) {
      const CellType t = mesh.cell_types[c];
      const PointId* nodes = mesh.cell_nodes(c);
      bool finite = true;
      for (int i = 0; i < corner_count(t); ++i) {
        p[i] = mesh.points[nodes[i]];
        finite = finite && is_finite(p[i]);
      }
      if (!finite) {
        r.validity[c] = Validity::kInverted;
        r.flags[c] = bit(CellCheckFlag::kInverted) | bit(CellCheckFlag::kNonFinite);
        continue;
      }
      const Validity v = cell_validity(t, p);
      r.validity[c] = v;
      if (v == Validity::kFlat) r.flags[c] = bit(CellCheckFlag::kFlat);
      if (v == Validity::kInverted) r.flags[c] = bit(CellCheckFlag::kInverted);
      if (v == Validity::kTwisted) r.flags[c] = bit(CellCheckFlag::kTwisted);
      const CellMetrics m = compute_cell_metrics(t, p);
      r.metrics[kJac][c] = m.scaled_jacobian;
      r.metrics[kSkew][c] = m.skewness;
      r.metrics[kAspect][c] = m.aspect_ratio;
      r.metrics[kOrtho][c] = m.orthogonality_deg;
      r.metrics[kTwist][c] = m.twist_deg;
      r.metrics[kVolume][c] = m.volume;
    }
  });

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
    for (std::size_t c = range.begin(); c < range.end(); ++c) {
      r.flags[c] |= face_flags[c].load(std::memory_order_relaxed);
      const std::int64_t u = r.upper_neighbour[c];
      if (u >= 0) r.metrics[kGrowth][c] = r.metrics[kVolume][u] / r.metrics[kVolume][c];
    }
  });

  const bool full = summaries == CheckSummaries::kFull;
  r.totals = count_cells<std::size_t>(mesh, r, nullptr, n, full);
  if (!full) return r;

  const DataArray* layer = mesh.find_cell_array("layer");
  if (layer && layer->n_components == 1 && layer->values.size() == n) {
    if (n <= std::numeric_limits<std::uint32_t>::max())
      count_layers<std::uint32_t>(mesh, *layer, &r);
    else
      count_layers<std::size_t>(mesh, *layer, &r);
  }
  return r;
}

}  // namespace blayer
