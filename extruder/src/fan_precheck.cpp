#include "fan_precheck.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

#include "blayer/extruder/layer_cells.h"

namespace blayer {

namespace {

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

std::uint64_t hash_words(const std::uint64_t* w, std::size_t n) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull ^ n;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= w[i] + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
  }
  return h ^ (h >> 31);
}

}  // namespace

bool FanPrecheck::ElementKey::operator<(const ElementKey& o) const {
  if (kind != o.kind) return kind < o.kind;
  if (split_at != o.split_at) return split_at < o.split_at;
  return std::lexicographical_compare(runs, runs + 4, o.runs, o.runs + 4);
}

int FanPrecheck::Round::find(const std::uint64_t* t, std::size_t n, std::uint64_t hash) const {
  auto it = std::lower_bound(by_hash.begin(), by_hash.end(), std::make_pair(hash, -1));
  for (; it != by_hash.end() && it->first == hash; ++it) {
    const std::size_t begin = run_start[it->second], end = run_start[it->second + 1];
    if (end - begin == n && std::equal(t, t + n, runs.begin() + static_cast<std::ptrdiff_t>(begin))) return it->second;
  }
  return -1;
}

FanPrecheck::Round FanPrecheck::round_of(const TriSurface& wall, const ColumnLayout& layout,
                                         const WallPlanes& planes, const StepDirections& dirs, const ColumnPlan& plan,
                                         const ExtrusionParams& params, const std::vector<char>& needed) {
  const int nc = layout.n_columns();
  // Each column's run has a known length (its point, whether it grows the first layer,
  // and then the three words of that layer's top; none for a column no checked element
  // holds): laid out first, then the columns are filled and hashed in parallel.
  std::vector<char> grows(nc);
  Round r;
  r.run_start.assign(static_cast<std::size_t>(nc) + 1, 0);
  for (int c = 0; c < nc; ++c) {
    grows[c] = dirs.ok[c] && std::min(plan.planned_layers[c], plan.n_layers) > 0;
    r.run_start[c + 1] = r.run_start[c] + (needed[c] ? (grows[c] ? 5 : 2) : 0);
  }
  r.runs.resize(r.run_start[nc]);
  r.by_hash.resize(nc);
  tbb::parallel_for(0, nc, [&](int c) {
    if (!needed[c]) {
      r.by_hash[c] = {0, -1};
      return;
    }
    const int w = layout.wall_point[c];
    std::uint64_t* out = r.runs.data() + r.run_start[c];
    *out++ = static_cast<std::uint64_t>(w);
    *out++ = static_cast<std::uint64_t>(grows[c]);
    if (grows[c]) {
      const Vec3& p = wall.points[w];
      const double h = plan.cumulative(c, 0);
      const Vec3 top =
          p + std::clamp(planes.step_to_height(c, p, dirs.n[c], h), h, params.max_step_stretch * h) * dirs.n[c];
      for (double x : top) *out++ = bits(x);
    }
    r.by_hash[c] = {hash_words(r.runs.data() + r.run_start[c], r.run_start[c + 1] - r.run_start[c]), c};
  });
  r.by_hash.erase(std::remove_if(r.by_hash.begin(), r.by_hash.end(), [](const auto& h) { return h.second < 0; }),
                  r.by_hash.end());
  return r;
}

bool FanPrecheck::Round::grows(int c) const {
  return run_start[c + 1] != run_start[c] && runs[run_start[c] + 1] != 0;
}

Vec3 FanPrecheck::Round::top(int c) const {
  const std::uint64_t* t = runs.data() + run_start[c] + 2;
  return {from_bits(t[0]), from_bits(t[1]), from_bits(t[2])};
}

FanPrecheck::ElementKey FanPrecheck::key_of(const LayerElement& e, const std::vector<int>* run) {
  ElementKey k;
  k.kind = static_cast<int>(e.kind);
  k.split_at = e.split_at;
  for (int j = 0; j < e.n_columns(); ++j) k.runs[j] = run ? (*run)[e.column[j]] : e.column[j];
  return k;
}

std::vector<signed char> FanPrecheck::passed_before(const ColumnLayout& layout, const std::vector<std::size_t>& checked,
                                                    const Round& current) const {
  const int nc = layout.n_columns();
  std::vector<int> previous_run(nc);
  tbb::parallel_for(0, nc, [&](int c) {
    const std::size_t begin = current.run_start[c], n = current.run_start[c + 1] - begin;
    const std::uint64_t* t = current.runs.data() + begin;
    previous_run[c] = n == 0 ? -1 : previous_.find(t, n, hash_words(t, n));
  });
  std::vector<signed char> passed(checked.size(), 0);
  tbb::parallel_for(std::size_t{0}, checked.size(), [&](std::size_t x) {
    const LayerElement& e = layout.elements[checked[x]];
    bool known = true;
    for (int j = 0; j < e.n_columns() && known; ++j) known = previous_run[e.column[j]] >= 0;
    if (known && std::binary_search(previous_.passed.begin(), previous_.passed.end(), key_of(e, &previous_run)))
      passed[x] = 1;
  });
  return passed;
}

std::vector<int> FanPrecheck::failing_points(const TriSurface& wall, const ColumnLayout& layout,
                                             const WallPlanes& planes, const StepDirections& dirs,
                                             const ColumnPlan& plan, const ExtrusionParams& params,
                                             bool last_round) {
  const int nv = static_cast<int>(wall.points.size()), nc = layout.n_columns();
  const std::size_t n_wall_elements = wall.triangles.size();
  std::vector<std::size_t> checked;
  for (std::size_t i = 0; i < layout.elements.size(); ++i) {
    const LayerElement& e = layout.elements[i];
    bool fan = i >= n_wall_elements || e.split_at >= 0;
    for (int j = 0; j < 3 && !fan; ++j) fan = layout.in_fan[e.column[j]];
    if (fan) checked.push_back(i);
  }
  // Only the columns of the checked elements are followed (on the ONERA M6 571k, 470
  // of 286,000 columns are fan columns; following them all took 0.2 s a round).
  std::vector<char> needed(nc, 0);
  for (std::size_t i : checked)
    for (int j = 0; j < layout.elements[i].n_columns(); ++j) needed[layout.elements[i].column[j]] = 1;
  Round current = round_of(wall, layout, planes, dirs, plan, params, needed);
  // 1: passed as the previous round's; 0: to be checked; -1: failed or left unchecked.
  std::vector<signed char> passed = passed_before(layout, checked, current);
  reused_ = static_cast<std::size_t>(std::count(passed.begin(), passed.end(), 1));
  previous_ = Round{};  // not needed any more: one round's records at a time

  std::vector<char> failed(nv, 0);
  // A fan column without a usable direction stops on the wall, and its fan with it.
  for (int c = 0; c < nc; ++c)
    if (layout.in_fan[c] && !dirs.ok[c]) failed[layout.wall_point[c]] = 1;
  // The first layer only. A fan cell that folds higher up (a short ridge edge under tall
  // layers) is left to the march, which lowers or stops the columns of a failing cell
  // there as anywhere else (a fan's columns stop together). Falling the point back
  // instead made each neighbour on the ridge a ridge end whose split cells folded in the
  // next round, a cascade that took every fan of a perforated CAD block
  // (bench/make_perforated_block.py). A fan that fails its first layer grows nothing and
  // would fall back after a marching attempt anyway: found here, it costs no rerun.
  // Column tops: ids nv + c.
  std::vector<Vec3> up(nc);
  std::vector<char> grows(nc, 0);
  for (int c = 0; c < nc; ++c) {
    if (!current.grows(c)) continue;
    up[c] = current.top(c);
    grows[c] = 1;
  }
  // The elements are checked in parallel; the verdicts are merged in element order, so
  // the failed set does not depend on the scheduling. An element whose fan points all
  // failed already (no direction) can add nothing and is not recorded as passed.
  std::vector<char> bad(checked.size(), 0);
  tbb::parallel_for(std::size_t{0}, checked.size(), [&](std::size_t x) {
    if (passed[x] != 0) return;
    const LayerElement& e = layout.elements[checked[x]];
    bool news = false;
    for (int j = 0; j < e.n_columns() && !news; ++j)
      news = layout.in_fan[e.column[j]] && !failed[layout.wall_point[e.column[j]]];
    if (!news) {
      passed[x] = -1;
      return;
    }
    LayerCell cells[2];
    const int n_cells = element_layer_cells(
        e, [&](int c) -> std::int64_t { return layout.wall_point[c]; },
        [&](int c) -> std::int64_t { return static_cast<std::int64_t>(nv) + c; },
        [&](int c) { return grows[c] != 0; }, cells);
    for (int q = 0; q < n_cells; ++q) {
      Vec3 corners[8];
      for (int j = 0; j < corner_count(cells[q].type); ++j) {
        const std::int64_t id = cells[q].nodes[j];
        corners[j] = id < nv ? wall.points[id] : up[id - nv];
      }
      if (!layer_cell_accepted(e, cells[q], corners)) {
        bad[x] = 1;
        passed[x] = -1;
        return;
      }
    }
  });
  for (std::size_t x = 0; x < checked.size(); ++x) {
    if (!bad[x]) continue;
    const LayerElement& e = layout.elements[checked[x]];
    for (int j = 0; j < e.n_columns(); ++j)
      if (layout.in_fan[e.column[j]]) failed[layout.wall_point[e.column[j]]] = 1;
  }
  std::vector<int> out;
  for (int w = 0; w < nv; ++w)
    if (failed[w]) out.push_back(w);
  // Only a failing round is followed by another (a passing one marches, and release()
  // drops the records), so a passing round keeps none.
  if (out.empty() || last_round) return out;
  std::sort(current.by_hash.begin(), current.by_hash.end());
  for (std::size_t x = 0; x < checked.size(); ++x)
    if (passed[x] >= 0) current.passed.push_back(key_of(layout.elements[checked[x]], nullptr));
  std::sort(current.passed.begin(), current.passed.end());
  previous_ = std::move(current);
  return out;
}

void FanPrecheck::release() { previous_ = Round{}; }

}  // namespace blayer
