#include "blayer/quality/layer_fidelity.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "blayer/core/triangle_ids.h"
#include "nearest_triangle.h"

namespace blayer {

namespace {

// The column edges of the layer cells, wall end first where a cell stands on the wall
// (VTK node orders: a wedge's bottom 0 1 2 under 3 4 5; a closure pyramid's base edges
// 0-1 and 3-2 run up the two columns that grew).
constexpr int kWedgeEdges[3][2] = {{0, 3}, {1, 4}, {2, 5}};
constexpr int kHexEdges[4][2] = {{0, 4}, {1, 5}, {2, 6}, {3, 7}};
constexpr int kPyramidEdges[2][2] = {{0, 1}, {3, 2}};

// Column edges as an adjacency list: for each mesh point the points it shares a column
// edge with, each neighbour once, in the order the cells first name them. Most points
// have one or two (the points below and above them), so those are stored inline and
// only the rest (fan points) in a map: one vector per point of a 5.7M-cell mesh took
// about 0.9 GB.
class ColumnGraph {
 public:
  explicit ColumnGraph(const VolumeMesh& mesh) : first_(2 * mesh.points.size(), -1), n_inline_(mesh.points.size(), 0) {
    auto link_one = [&](std::int64_t a, std::int64_t b) {
      std::int64_t* in = &first_[2 * a];
      for (int i = 0; i < n_inline_[a]; ++i)
        if (in[i] == b) return;
      if (n_inline_[a] < 2) {
        in[n_inline_[a]++] = b;
        return;
      }
      std::vector<std::int64_t>& more = more_[a];
      if (std::find(more.begin(), more.end(), b) == more.end()) more.push_back(b);
    };
    auto link = [&](std::int64_t a, std::int64_t b) {
      if (a == b) return;
      link_one(a, b);
      link_one(b, a);
    };
    for (std::size_t c = 0; c < mesh.n_cells(); ++c) {
      const PointId* n = mesh.cell_nodes(c);
      if (mesh.cell_types[c] == CellType::kWedge) {
        for (const auto& e : kWedgeEdges) link(n[e[0]], n[e[1]]);
      } else if (mesh.cell_types[c] == CellType::kHex) {
        for (const auto& e : kHexEdges) link(n[e[0]], n[e[1]]);
      } else if (mesh.cell_types[c] == CellType::kPyramid) {
        for (const auto& e : kPyramidEdges) link(n[e[0]], n[e[1]]);
      }
    }
  }

  std::size_t size() const { return n_inline_.size(); }

  // fn(q) for every neighbour q of point p, in order.
  template <class Fn>
  void for_each(std::int64_t p, Fn&& fn) const {
    for (int i = 0; i < n_inline_[p]; ++i) fn(first_[2 * p + i]);
    if (n_inline_[p] < 2) return;
    const auto it = more_.find(p);
    if (it != more_.end())
      for (std::int64_t q : it->second) fn(q);
  }

 private:
  std::vector<std::int64_t> first_;       // the first two neighbours of each point
  std::vector<std::uint8_t> n_inline_;    // how many of them there are (0 to 2)
  std::unordered_map<std::int64_t, std::vector<std::int64_t>> more_;  // the rest
};

// A column edge continues a column when it turns by less than 60 degrees from the
// column's previous segment: edges that run along a ridge or across a fan (fan wedges,
// strip closures) turn by about 90 degrees and are not followed.
constexpr double kMinContinuationCosine = 0.5;

// The column that leaves wall point w through its first point q: q and the points
// after it, in order, into *out. Where a point has several onward column edges, the
// one best aligned with the column's last segment is followed if it turns by less than
// 60 degrees; *branching is set when another one also does. The caller's *out keeps its
// capacity from column to column: the run's malloc has one arena, and the threads'
// allocations of a path per column waited on each other.
void follow_column(std::int64_t w, std::int64_t q, const VolumeMesh& mesh, const ColumnGraph& nb, std::size_t n_wall,
                   std::vector<std::int64_t>* out, bool* branching) {
  std::vector<std::int64_t>& path = *out;
  path.assign(1, q);
  std::int64_t prev = w, cur = q;
  *branching = false;
  // A column cannot be longer than the mesh has points; the bound also stops a cycle.
  while (path.size() < nb.size()) {
    const Vec3 last = normalized(mesh.points[cur] - mesh.points[prev]);
    std::int64_t next = -1;
    double best = kMinContinuationCosine;
    int aligned = 0;
    nb.for_each(cur, [&](std::int64_t c) {
      if (c == prev || static_cast<std::size_t>(c) < n_wall) return;
      if (std::find(path.begin(), path.end(), c) != path.end()) return;
      const double cosine = dot(normalized(mesh.points[c] - mesh.points[cur]), last);
      if (!(cosine >= kMinContinuationCosine)) return;
      ++aligned;
      if (cosine >= best) {
        best = cosine;
        next = c;
      }
    });
    if (aligned > 1) *branching = true;
    if (next < 0) break;
    path.push_back(next);
    prev = cur;
    cur = next;
  }
}

// The first points of the columns leaving each wall point (column edges to a point
// off the wall), ascending.
std::vector<std::vector<std::int64_t>> column_starts(const ColumnGraph& nb, std::size_t n_wall) {
  std::vector<std::vector<std::int64_t>> starts(n_wall);
  for (std::size_t w = 0; w < n_wall; ++w) {
    nb.for_each(static_cast<std::int64_t>(w), [&](std::int64_t q) {
      if (static_cast<std::size_t>(q) >= n_wall) starts[w].push_back(q);
    });
    std::sort(starts[w].begin(), starts[w].end());
  }
  return starts;
}

// The wall triangles each first point of a fan (a wall point with several columns)
// stands on: those whose wall-layer wedge or closure pyramid (its base on the
// triangle's three points) has the column edge from the wall to it, so that each of
// the fan's columns is measured above its own faces' planes. Other columns use all
// their point's triangles and need no entry.
std::unordered_map<std::int64_t, std::vector<int>> first_point_triangles(
    const VolumeMesh& mesh, const TriSurface& wall, const std::vector<std::vector<std::int64_t>>& starts) {
  const std::int64_t n_wall = static_cast<std::int64_t>(wall.points.size());
  std::unordered_map<std::int64_t, std::vector<int>> out;
  std::vector<char> fan_point(wall.points.size(), 0);
  for (std::size_t w = 0; w < starts.size(); ++w)
    if (starts[w].size() > 1) {
      fan_point[w] = 1;
      for (std::int64_t q : starts[w]) out[q];
    }
  if (out.empty()) return out;
  // Only triangles at a fan point can be the base of a cell with an edge to a fan's first
  // point (that edge leaves the fan point): the table holds those alone.
  std::map<TriangleKey, int> triangle_of;
  for (std::size_t t = 0; t < wall.triangles.size(); ++t) {
    const Triangle& w = wall.triangles[t];
    if (fan_point[w[0]] || fan_point[w[1]] || fan_point[w[2]])
      triangle_of[sorted_triangle(w[0], w[1], w[2])] = static_cast<int>(t);
  }
  for (std::size_t c = 0; c < mesh.n_cells(); ++c) {
    const PointId* n = mesh.cell_nodes(c);
    const bool wedge = mesh.cell_types[c] == CellType::kWedge;
    if (!wedge && mesh.cell_types[c] != CellType::kPyramid) continue;
    const TriangleKey base = wedge ? sorted_triangle(n[0], n[1], n[2]) : sorted_triangle(n[0], n[3], n[4]);
    if (base[2] >= n_wall) continue;  // the largest id: all three on the wall
    auto add = [&](const int(*edges)[2], int count) {
      for (int e = 0; e < count; ++e) {
        const std::int64_t a = n[edges[e][0]], b = n[edges[e][1]];
        if (a >= n_wall || b < n_wall) continue;
        const auto fan_first = out.find(b);
        if (fan_first == out.end()) continue;
        const auto it = triangle_of.find(base);
        if (it != triangle_of.end()) fan_first->second.push_back(it->second);
      }
    };
    if (wedge)
      add(kWedgeEdges, 3);
    else
      add(kPyramidEdges, 2);
  }
  return out;
}

double percentile(const std::vector<double>& sorted, double p) {
  const double pos = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  const double t = pos - static_cast<double>(lo);
  return sorted[lo] + t * (sorted[hi] - sorted[lo]);
}

double share(int count, int total) { return total > 0 ? static_cast<double>(count) / total : 0.0; }

nlohmann::json distribution_json(const FidelityDistribution& d) {
  return {{"count", d.count}, {"min", d.min}, {"p1", d.p1},   {"p5", d.p5},
          {"p50", d.p50},     {"p95", d.p95}, {"p99", d.p99}, {"max", d.max}};
}

}  // namespace

FidelityDistribution describe_distribution(std::vector<double> values) {
  FidelityDistribution d;
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  d.count = static_cast<int>(values.size());
  d.min = values.front();
  d.max = values.back();
  d.p1 = percentile(values, 1);
  d.p5 = percentile(values, 5);
  d.p50 = percentile(values, 50);
  d.p95 = percentile(values, 95);
  d.p99 = percentile(values, 99);
  return d;
}

LayerFidelity measure_layer_fidelity(const VolumeMesh& mesh, const TriSurface& wall,
                                     const LayerFidelityTargets& targets) {
  if (!(targets.first_height > 0.0) || !(targets.total_thickness > 0.0) || targets.layers <= 0)
    throw std::invalid_argument("layer fidelity: first height, total thickness and layers must be positive");
  const std::size_t n_wall = wall.points.size();
  if (n_wall > mesh.points.size())
    throw std::invalid_argument("layer fidelity: the wall has " + std::to_string(n_wall) + " points, the mesh only " +
                                std::to_string(mesh.points.size()));
  // Unit normal and a point of every wall triangle's plane, and the triangles at each point.
  std::vector<Vec3> unit_normal(wall.triangles.size());
  std::vector<std::vector<int>> incident(n_wall);
  for (std::size_t t = 0; t < wall.triangles.size(); ++t) {
    unit_normal[t] = normalized(triangle_area_vector(wall, wall.triangles[t]));
    for (int v : wall.triangles[t]) {
      if (v < 0 || static_cast<std::size_t>(v) >= n_wall)
        throw std::invalid_argument("layer fidelity: wall triangle " + std::to_string(t) + " uses point " +
                                    std::to_string(v) + ", not a wall point");
      incident[v].push_back(static_cast<int>(t));
    }
  }
  // The wall's tree is built beside the column graph and the fans' tables, which are
  // serial (15 and 14 ms of the perforated block's report, the tree 8-13 ms).
  std::optional<ColumnGraph> graph;
  std::vector<std::vector<std::int64_t>> starts;
  std::unordered_map<std::int64_t, std::vector<int>> own_triangles;
  std::optional<detail::NearestTriangleTree> wall_tree;
  tbb::parallel_invoke([&] { wall_tree.emplace(wall); },
                       [&] {
                         graph.emplace(mesh);
                         starts = column_starts(*graph, n_wall);
                         own_triangles = first_point_triangles(mesh, wall, starts);
                       });
  const ColumnGraph& nb = *graph;
  const detail::NearestTriangleTree& tree = *wall_tree;
  // Every wall point's columns, measured in parallel (follow_column and the nearest-point
  // queries are most of a report's time), then counted in point order, so the figures
  // do not depend on the schedule. Point w's columns are measured[column_begin[w] ..
  // column_begin[w + 1]), one per column leaving it (a point without a column edge off
  // the wall has one, without layers): one array for all, as an array per point made
  // the threads wait on each other in the run's one malloc arena.
  std::vector<std::size_t> column_begin(n_wall + 1, 0);
  for (std::size_t w = 0; w < n_wall; ++w)
    column_begin[w + 1] =
        column_begin[w] + (incident[w].empty() ? 0 : std::max<std::size_t>(1, starts[w].size()));
  std::vector<ColumnFidelity> measured(column_begin[n_wall]);
  std::vector<int> branching_columns(n_wall, 0);
  tbb::parallel_for(std::size_t(0), n_wall, [&](std::size_t w) {
    if (incident[w].empty()) return;
    for (std::size_t i = 0; i < starts[w].size(); ++i) {
      const std::int64_t q = starts[w][i];
      ColumnFidelity& c = measured[column_begin[w] + i];
      bool branching = false;
      thread_local std::vector<std::int64_t> path;
      follow_column(static_cast<std::int64_t>(w), q, mesh, nb, n_wall, &path, &branching);
      branching_columns[w] += branching ? 1 : 0;
      // The planes: all the point's triangles, or with a fan the column's own.
      const std::vector<int>* planes = &incident[w];
      if (starts[w].size() > 1) {
        const auto it = own_triangles.find(q);
        if (it != own_triangles.end() && !it->second.empty()) planes = &it->second;
      }
      auto height_planes = [&](const Vec3& p) {
        double h = std::numeric_limits<double>::infinity();
        for (int t : *planes) h = std::min(h, dot(p - wall.points[wall.triangles[t][0]], unit_normal[t]));
        return h;
      };
      c.layers = static_cast<int>(path.size());
      c.top_point = path.back();
      const Vec3& first = mesh.points[path.front()];
      const Vec3& top = mesh.points[path.back()];
      c.first_height_planes = height_planes(first);
      c.first_distance = tree.nearest(first).distance;
      c.top_height_planes = height_planes(top);
      c.top_distance = tree.nearest(top).distance;
    }
    if (starts[w].empty()) measured[column_begin[w]].top_point = static_cast<std::int64_t>(w);
  });
  LayerFidelity f;
  f.columns.resize(n_wall);
  std::vector<double> first_planes, first_distance, top_planes, top_distance;
  int within1_planes = 0, within1_distance = 0, within10_planes = 0, within10_distance = 0;
  int reach_planes = 0, reach_distance = 0;
  const double h1 = targets.first_height, total = targets.total_thickness;
  for (std::size_t w = 0; w < n_wall; ++w) {
    if (incident[w].empty()) {
      f.columns[w].layers = -1;
      continue;
    }
    if (starts[w].size() > 1) ++f.n_fan_points;
    f.n_branching += branching_columns[w];
    for (std::size_t i = 0; i < column_begin[w + 1] - column_begin[w]; ++i) {
      const ColumnFidelity& c = measured[column_begin[w] + i];
      ++f.n_columns;
      if (!starts[w].empty()) {
        ++f.n_grown;
        const double rp = c.first_height_planes / h1, rd = c.first_distance / h1;
        first_planes.push_back(rp);
        first_distance.push_back(rd);
        within1_planes += std::fabs(rp - 1.0) <= 0.01;
        within1_distance += std::fabs(rd - 1.0) <= 0.01;
        within10_planes += std::fabs(rp - 1.0) <= 0.1;
        within10_distance += std::fabs(rd - 1.0) <= 0.1;
      }
      if (c.layers >= targets.layers) ++f.n_complete;
      top_planes.push_back(c.top_height_planes / total);
      top_distance.push_back(c.top_distance / total);
      reach_planes += top_planes.back() >= 0.9;
      reach_distance += top_distance.back() >= 0.9;
      if (i == 0 || c.layers < f.columns[w].layers) f.columns[w] = c;  // the point's fewest layers
    }
  }
  f.first_over_h1_planes = describe_distribution(first_planes);
  f.first_over_h1_distance = describe_distribution(first_distance);
  f.top_over_T_planes = describe_distribution(top_planes);
  f.top_over_T_distance = describe_distribution(top_distance);
  f.first_within_1pct_planes = share(within1_planes, f.n_grown);
  f.first_within_1pct_distance = share(within1_distance, f.n_grown);
  f.first_within_10pct_planes = share(within10_planes, f.n_grown);
  f.first_within_10pct_distance = share(within10_distance, f.n_grown);
  f.top_ge_90pct_planes = share(reach_planes, f.n_columns);
  f.top_ge_90pct_distance = share(reach_distance, f.n_columns);
  f.complete_share = share(f.n_complete, f.n_columns);
  double area = 0.0, covered = 0.0;
  for (const Triangle& t : wall.triangles) {
    const double a = 0.5 * norm(triangle_area_vector(wall, t));
    area += a;
    bool complete = true;
    for (int v : t) complete &= f.columns[v].layers >= targets.layers;
    if (complete) covered += a;
  }
  f.area_coverage = area > 0.0 ? covered / area : 0.0;
  return f;
}

nlohmann::json layer_fidelity_to_json(const LayerFidelity& f) {
  nlohmann::json j;
  j["columns"] = f.n_columns;
  j["grown"] = f.n_grown;
  j["complete"] = f.n_complete;
  j["branching"] = f.n_branching;
  j["fan_points"] = f.n_fan_points;
  j["first_over_h1"] = {{"planes", distribution_json(f.first_over_h1_planes)},
                        {"distance", distribution_json(f.first_over_h1_distance)}};
  j["top_over_T"] = {{"planes", distribution_json(f.top_over_T_planes)},
                     {"distance", distribution_json(f.top_over_T_distance)}};
  j["first_within_1pct_planes"] = f.first_within_1pct_planes;
  j["first_within_1pct_distance"] = f.first_within_1pct_distance;
  j["first_within_10pct_planes"] = f.first_within_10pct_planes;
  j["first_within_10pct_distance"] = f.first_within_10pct_distance;
  j["top_ge_90pct_planes"] = f.top_ge_90pct_planes;
  j["top_ge_90pct_distance"] = f.top_ge_90pct_distance;
  j["complete_share"] = f.complete_share;
  j["area_coverage"] = f.area_coverage;
  return j;
}

VolumeMesh with_wall_points_first(const VolumeMesh& mesh, const TriSurface& wall) {
  // Points are matched within kMatchRelTol of the wall's bounding-box diagonal, and the
  // matched points take the wall's coordinates, which the measure is against: other
  // meshers read the same file with other parsers (a float and a double reading of an
  // ASCII STL differ by ~1e-7 relative), and no two distinct points of a layer mesh are
  // that close (the first height alone is ~1e-4 of the diagonal).
  constexpr double kMatchRelTol = 1e-6;
  Vec3 lo = wall.points.empty() ? Vec3{0, 0, 0} : wall.points[0], hi = lo;
  for (const Vec3& p : wall.points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  const double tol = std::max(kMatchRelTol * norm(hi - lo), std::numeric_limits<double>::min());
  using Cell = std::array<long long, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  auto cell_of = [&](const Vec3& q) {
    return Cell{static_cast<long long>(std::floor(q[0] / tol)), static_cast<long long>(std::floor(q[1] / tol)),
                static_cast<long long>(std::floor(q[2] / tol))};
  };
  std::unordered_map<Cell, std::vector<std::int64_t>, CellHash> grid;
  grid.reserve(mesh.points.size());
  for (std::size_t p = 0; p < mesh.points.size(); ++p) grid[cell_of(mesh.points[p])].push_back(static_cast<std::int64_t>(p));
  auto nearest = [&](const Vec3& w) {
    const Cell c = cell_of(w);
    std::int64_t best = -1;
    double best_d = tol;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(Cell{c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (std::int64_t p : it->second) {
            const double d = norm(mesh.points[p] - w);
            if (d <= best_d) {
              best_d = d;
              best = p;
            }
          }
        }
    return best;
  };
  const std::int64_t nv = static_cast<std::int64_t>(wall.points.size());
  std::vector<std::int64_t> renumber(mesh.points.size(), -1);
  for (std::int64_t v = 0; v < nv; ++v) {
    const std::int64_t p = nearest(wall.points[v]);
    if (p < 0) throw std::invalid_argument("wall point " + std::to_string(v) + " is not a point of the mesh");
    if (renumber[p] < 0) renumber[p] = v;
  }
  VolumeMesh out;
  out.points = wall.points;
  std::int64_t next = nv;
  for (std::size_t p = 0; p < mesh.points.size(); ++p)
    if (renumber[p] < 0) {
      renumber[p] = next++;
      out.points.push_back(mesh.points[p]);
    }
  out.points.resize(next);
  for (std::size_t c = 0; c < mesh.n_cells(); ++c) {
    std::int64_t nodes[8];
    const std::int64_t o = mesh.offsets[c];
    const int n = corner_count(mesh.cell_types[c]);
    for (int i = 0; i < n; ++i) nodes[i] = renumber[mesh.connectivity[o + i]];
    out.add_cell(mesh.cell_types[c], nodes);
  }
  out.cell_data = mesh.cell_data;
  return out;
}

}  // namespace blayer
