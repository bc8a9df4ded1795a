#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
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

void check_structure(const VolumeMesh& mesh) {
  const std::size_t n = mesh.n_cells();
  if (mesh.offsets.size() != n + 1 || mesh.offsets.front() != 0)
    throw InputError("check_volume_mesh: offsets has " + std::to_string(mesh.offsets.size()) +
                     " entries for " + std::to_string(n) + " cells (expected n_cells + 1, starting at 0)");
  if (mesh.offsets.back() != static_cast<std::int64_t>(mesh.connectivity.size()))
    throw InputError("check_volume_mesh: last offset " + std::to_string(mesh.offsets.back()) +
                     " differs from the connectivity size " + std::to_string(mesh.connectivity.size()));
  const auto n_points = static_cast<std::int64_t>(mesh.points.size());
  for (std::size_t c = 0; c < n; ++c) {
    const int k = corner_count(mesh.cell_types[c]);
    if (k == 0) throw InputError("check_volume_mesh: cell " + std::to_string(c) + " has an unsupported type");
    if (mesh.offsets[c + 1] - mesh.offsets[c] != k)
      throw InputError("check_volume_mesh: cell " + std::to_string(c) + " (" + cell_type_name(mesh.cell_types[c]) +
                       ") has " + std::to_string(mesh.offsets[c + 1] - mesh.offsets[c]) + " nodes, expected " +
                       std::to_string(k));
    for (std::int64_t i = mesh.offsets[c]; i < mesh.offsets[c + 1]; ++i)
      if (mesh.connectivity[i] < 0 || mesh.connectivity[i] >= n_points)
        throw InputError("check_volume_mesh: cell " + std::to_string(c) + " uses node " +
                         std::to_string(mesh.connectivity[i]) + ", outside [0, " + std::to_string(n_points) + ")");
  }
}

// A face of a cell as global node ids, in canonical form: `cyclic` starts at the
// smallest node and continues in the direction whose next node is smaller; `reversed`
// says that this is against the cell's outward winding. `sorted` is the node set.
struct FaceKey {
  int n = 0;
  std::array<std::int64_t, 4> cyclic{-1, -1, -1, -1};
  std::array<std::int64_t, 4> sorted{-1, -1, -1, -1};
  bool reversed = false;
};

FaceKey face_key(const VolumeMesh& mesh, std::int64_t cell, int face) {
  const detail::FaceDef& fd = detail::cell_faces(mesh.cell_types[cell]).faces[face];
  const PointId* nodes = mesh.cell_nodes(cell);
  FaceKey k;
  k.n = fd.n;
  std::array<std::int64_t, 4> v{};
  int lo = 0;
  for (int i = 0; i < fd.n; ++i) {
    v[i] = nodes[fd.v[i]];
    if (v[i] < v[lo]) lo = i;
  }
  std::array<std::int64_t, 4> fwd{-1, -1, -1, -1}, bwd{-1, -1, -1, -1};
  for (int i = 0; i < fd.n; ++i) {
    fwd[i] = v[cyclic_wrap(lo + i, fd.n)];
    bwd[i] = v[cyclic_wrap(lo - i, fd.n)];
  }
  k.reversed = bwd < fwd;
  k.cyclic = k.reversed ? bwd : fwd;
  k.sorted = k.cyclic;
  // Insertion sort of the 3 or 4 ids (the -1 padding of a triangle stays last).
  for (int i = 1; i < fd.n && i < 4; ++i)
    for (int j = i; j > 0 && k.sorted[j] < k.sorted[j - 1]; --j) std::swap(k.sorted[j], k.sorted[j - 1]);
  return k;
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

struct BucketEntry {
  FaceKey key;
  std::int64_t cell;
  int face;
};

bool same_face(const BucketEntry& a, const BucketEntry& b) { return a.key.n == b.key.n && a.key.sorted == b.key.sorted; }

// Face matching: fills flags (atomic bit-or), upper_neighbour and the counters.
void match_faces(const VolumeMesh& mesh, std::atomic<std::uint8_t>* flags, std::vector<std::int64_t>& upper,
                 FaceCounters* totals) {
  const FaceBuckets b = bucket_faces(mesh);
  const std::size_t n_points = mesh.points.size();
  tbb::combinable<FaceCounters> counters;
  auto mark = [&](std::int64_t cell, CellCheckFlag f) { flags[cell].fetch_or(bit(f), std::memory_order_relaxed); };

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_points, 1024), [&](const auto& r) {
    FaceCounters& fc = counters.local();
    std::vector<BucketEntry> entries;
    for (std::size_t m = r.begin(); m < r.end(); ++m) {
      entries.clear();
      for (std::int64_t i = b.start[m]; i < b.start[m + 1]; ++i) {
        const auto cell = static_cast<std::int64_t>(b.records[i] / 8);
        const int face = static_cast<int>(b.records[i] % 8);
        entries.push_back({face_key(mesh, cell, face), cell, face});
      }
      // Sorting makes the grouping (and so the result) independent of the fill order.
      std::sort(entries.begin(), entries.end(), [](const BucketEntry& x, const BucketEntry& y) {
        if (x.key.n != y.key.n) return x.key.n < y.key.n;
        if (x.key.sorted != y.key.sorted) return x.key.sorted < y.key.sorted;
        if (x.key.cyclic != y.key.cyclic) return x.key.cyclic < y.key.cyclic;
        return x.cell < y.cell;
      });
      for (std::size_t g = 0; g < entries.size();) {
        std::size_t e = g + 1;
        while (e < entries.size() && same_face(entries[g], entries[e])) ++e;
        const std::size_t size = e - g;
        bool same_cyclic = true;
        for (std::size_t i = g + 1; i < e; ++i) same_cyclic = same_cyclic && entries[i].key.cyclic == entries[g].key.cyclic;
        if (!same_cyclic) {
          ++fc.non_conforming;
          for (std::size_t i = g; i < e; ++i) mark(entries[i].cell, CellCheckFlag::kNonConforming);
        } else if (size > 2) {
          ++fc.overshared;
          for (std::size_t i = g; i < e; ++i) mark(entries[i].cell, CellCheckFlag::kOversharedFace);
        } else if (size == 2) {
          const BucketEntry& x = entries[g];
          const BucketEntry& y = entries[g + 1];
          if (x.key.reversed == y.key.reversed) {
            ++fc.misoriented;
            mark(x.cell, CellCheckFlag::kMisorientedFace);
            mark(y.cell, CellCheckFlag::kMisorientedFace);
          } else {
            const detail::CellFaces& cx = detail::cell_faces(mesh.cell_types[x.cell]);
            const detail::CellFaces& cy = detail::cell_faces(mesh.cell_types[y.cell]);
            if (x.face == cx.top_cap && y.face == cy.bottom_cap) upper[x.cell] = y.cell;
            if (y.face == cy.top_cap && x.face == cx.bottom_cap) upper[y.cell] = x.cell;
          }
        } else if (entries[g].key.n == 4) {
          // An unmatched quad: look for triangles on three of its nodes in the buckets
          // of those triangles' smallest nodes.
          const BucketEntry& q = entries[g];
          std::size_t found = 0;
          for (int skip = 0; skip < 4; ++skip) {
            std::array<std::int64_t, 4> tri{-1, -1, -1, -1};
            for (int i = 0, j = 0; i < 4; ++i)
              if (i != skip) tri[j++] = q.key.sorted[i];
            const auto tm = static_cast<std::size_t>(tri[0]);
            for (std::int64_t i = b.start[tm]; i < b.start[tm + 1]; ++i) {
              const auto cell = static_cast<std::int64_t>(b.records[i] / 8);
              const int face = static_cast<int>(b.records[i] % 8);
              if (cell == q.cell || detail::cell_faces(mesh.cell_types[cell]).faces[face].n != 3) continue;
              if (face_key(mesh, cell, face).sorted != tri) continue;
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

  r.validity.assign(n, Validity::kValid);
  r.flags.assign(n, 0);
  for (std::vector<double>& m : r.metrics) m.assign(n, kNaN);
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
