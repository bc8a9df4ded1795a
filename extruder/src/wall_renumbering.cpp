#include "blayer/extruder/wall_renumbering.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <numeric>
#include <type_traits>
#include <utility>

#include "blayer/core/assert.h"
#include "blayer/core/edge_topology.h"
#include "blayer/core/spatial_order.h"

namespace blayer {

namespace {

// The wall point a renumbered mesh point id stands for; layer points keep their ids.
template <class Id>
Id wall_id(const WallRenumbering& r, Id id) {
  return id >= 0 && id < static_cast<Id>(r.point_source.size()) ? static_cast<Id>(r.point_source[id]) : id;
}

// Moves rows 0..V-1 of a point array (V = the wall's point count) to their wall indices.
void restore_wall_rows(const WallRenumbering& r, DataArray* a) {
  const int c = a->n_components;
  const std::size_t n_wall = r.point_source.size();
  std::vector<double> rows(n_wall * c);
  for (std::size_t i = 0; i < n_wall * c; ++i) rows[i] = a->values[i];
  for (std::size_t i = 0; i < n_wall; ++i)
    for (int k = 0; k < c; ++k) a->values.set(r.point_source[i] * static_cast<std::size_t>(c) + k, rows[i * c + k]);
}

void restore_mesh(const WallRenumbering& r, VolumeMesh* mesh) {
  const std::size_t n_wall = r.point_source.size();
  BLAYER_ASSERT_MSG(mesh->points.size() >= n_wall, "the mesh starts with the wall's points");
  const std::vector<Vec3> wall_points(mesh->points.begin(), mesh->points.begin() + n_wall);
  for (std::size_t i = 0; i < n_wall; ++i) mesh->points[r.point_source[i]] = wall_points[i];
  std::vector<PointId>& ids = mesh->connectivity;
  tbb::parallel_for(std::size_t{0}, ids.size(), [&](std::size_t i) { ids[i] = wall_id(r, ids[i]); });
  for (DataArray& a : mesh->point_data) {
    BLAYER_ASSERT_MSG(a.values.size() == mesh->points.size() * a.n_components, "a point array has a row per point");
    restore_wall_rows(r, &a);
  }
}

// The envelope's first F triangles stand on wall triangles 0..F-1 in order (the front
// starts with the wall's triangles): put each back at its wall triangle's index.
void restore_envelope(const WallRenumbering& r, ExtrusionResult* res) {
  const std::size_t n_wall = r.triangle_source.size();
  std::vector<Triangle>& tris = res->envelope.triangles;
  std::vector<int>& face = res->front_wall_face;
  BLAYER_ASSERT_MSG(tris.size() >= n_wall && face.size() == tris.size(), "the envelope starts with the wall's triangles");
  const std::vector<Triangle> on_wall(tris.begin(), tris.begin() + n_wall);
  for (std::size_t j = 0; j < n_wall; ++j) {
    BLAYER_ASSERT_MSG(face[j] == static_cast<int>(j), "envelope triangle j stands on wall triangle j");
    tris[r.triangle_source[j]] = on_wall[j];
  }
  for (std::size_t j = 0; j < face.size(); ++j)
    if (face[j] >= 0) face[j] = j < n_wall ? static_cast<int>(j) : r.triangle_source[face[j]];
}

// Numbers the columns by their wall points, in the wall's order, a fan point's columns
// together in their order of the march (stable): one column per point gives column v at
// wall point v, as extrude_layers does. Per-column arrays and the envelope follow; the
// layer points keep their numbers (envelope_point_ids says which is whose).
void restore_column_order(ExtrusionResult* res) {
  const std::vector<int>& wall_point = res->column_wall_point;  // already the wall's ids
  const int n = static_cast<int>(wall_point.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return wall_point[a] < wall_point[b]; });
  std::vector<int> new_index(n);
  for (int i = 0; i < n; ++i) new_index[order[i]] = i;
  auto permuted = [&](const auto& per_column) {
    std::decay_t<decltype(per_column)> out(per_column.size());
    for (int i = 0; i < n; ++i) out[i] = per_column[order[i]];
    return out;
  };
  BLAYER_ASSERT_MSG(res->envelope.points.size() == static_cast<std::size_t>(n) &&
                        res->envelope_point_ids.size() == static_cast<std::size_t>(n) &&
                        res->column_layers.size() == static_cast<std::size_t>(n) &&
                        res->stop_reason.size() == static_cast<std::size_t>(n),
                    "one envelope point and one entry of each per-column array per column");
  res->envelope.points = permuted(res->envelope.points);
  res->envelope_point_ids = permuted(res->envelope_point_ids);
  res->column_layers = permuted(res->column_layers);
  res->stop_reason = permuted(res->stop_reason);
  res->column_wall_point = permuted(res->column_wall_point);
  for (Triangle& t : res->envelope.triangles)
    for (int& c : t) c = new_index[c];
}

// Pairs (j, k), j < k, of the triangles sharing each edge that two triangles share.
std::vector<std::array<int, 2>> edge_neighbour_pairs(const TriSurface& wall) {
  std::vector<std::array<int, 2>> pairs;
  for (const SurfaceEdge& e : build_edge_topology(wall).edges)
    if (e.n_uses == 2) pairs.push_back(e.triangle);
  return pairs;
}

// The geometric mean spread of neighbours' positions: the mean of log2(1 + |position
// of j - position of k|) over the pairs (position: where a triangle sits in a
// numbering; empty: the wall's own).
double neighbour_spread_bits(const std::vector<std::array<int, 2>>& pairs, const std::vector<int>& position) {
  if (pairs.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& [j, k] : pairs) {
    const int d = position.empty() ? k - j : std::abs(position[j] - position[k]);
    sum += std::log2(1.0 + d);
  }
  return sum / static_cast<double>(pairs.size());
}

}  // namespace

WallRenumbering spatial_renumbering(const TriSurface& wall) {
  WallRenumbering r;
  std::vector<Vec3> centroids(wall.triangles.size());
  for (std::size_t j = 0; j < wall.triangles.size(); ++j) {
    const Triangle& t = wall.triangles[j];
    centroids[j] = (wall.points[t[0]] + wall.points[t[1]] + wall.points[t[2]]) / 3.0;
  }
  const std::vector<int> triangles = morton_order(centroids);
  std::vector<int> position(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) position[triangles[i]] = static_cast<int>(i);
  const std::vector<std::array<int, 2>> pairs = edge_neighbour_pairs(wall);
  r.input_spread_bits = neighbour_spread_bits(pairs, {});
  r.spatial_spread_bits = neighbour_spread_bits(pairs, position);
  if (r.spatial_spread_bits > r.input_spread_bits - kMinSpreadGainBits) {
    r.point_source.resize(wall.points.size());
    std::iota(r.point_source.begin(), r.point_source.end(), 0);
    r.triangle_source.resize(wall.triangles.size());
    std::iota(r.triangle_source.begin(), r.triangle_source.end(), 0);
    r.keeps_input_order = true;
    return r;
  }
  r.point_source = morton_order(wall.points);
  r.triangle_source = triangles;
  return r;
}

TriSurface renumbered_wall(const TriSurface& wall, const WallRenumbering& r) {
  std::vector<int> new_index(wall.points.size());
  TriSurface out;
  out.points.reserve(wall.points.size());
  for (std::size_t i = 0; i < r.point_source.size(); ++i) {
    new_index[r.point_source[i]] = static_cast<int>(i);
    out.points.push_back(wall.points[r.point_source[i]]);
  }
  out.triangles.reserve(wall.triangles.size());
  for (int j : r.triangle_source) {
    const Triangle& t = wall.triangles[j];
    out.triangles.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
  }
  return out;
}

TriSurface wall_in_input_order(const TriSurface& renumbered, const WallRenumbering& r) {
  TriSurface out;
  out.points.resize(renumbered.points.size());
  for (std::size_t i = 0; i < r.point_source.size(); ++i) out.points[r.point_source[i]] = renumbered.points[i];
  out.triangles.resize(renumbered.triangles.size());
  for (std::size_t j = 0; j < r.triangle_source.size(); ++j) {
    const Triangle& t = renumbered.triangles[j];
    out.triangles[r.triangle_source[j]] = {r.point_source[t[0]], r.point_source[t[1]], r.point_source[t[2]]};
  }
  return out;
}

void restore_wall_numbering(const WallRenumbering& r, ExtrusionResult* result) {
  restore_mesh(r, &result->mesh);
  restore_envelope(r, result);
  for (std::int64_t& id : result->envelope_point_ids) id = wall_id(r, id);
  for (int& v : result->column_wall_point) v = r.point_source[v];
  restore_column_order(result);
}

ExtrusionResult extrude_layers_in_spatial_order(TriSurface* wall, const ExtrusionParams& params,
                                                const std::function<void(int layer, int n_layers)>& progress) {
  const WallRenumbering r = spatial_renumbering(*wall);
  if (r.keeps_input_order) return extrude_layers(*wall, params, progress);
  // In place, not a copy: the wall's second copy would add to the run's peak memory.
  *wall = renumbered_wall(*wall, r);
  ExtrusionResult result;
  try {
    result = extrude_layers(*wall, params, progress);
  } catch (...) {
    *wall = wall_in_input_order(*wall, r);
    throw;
  }
  *wall = wall_in_input_order(*wall, r);
  restore_wall_numbering(r, &result);
  return result;
}

}  // namespace blayer
