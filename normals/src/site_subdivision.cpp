#include "site_subdivision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "candidate_families.h"

namespace blayer {
namespace detail {

namespace {

// A cell becomes a leaf when at most this many sites can be nearest in it: its
// enumeration is then a handful of candidates (at most two triples' worth).
constexpr int kLeafSites = 3;

// Sites that can be nearest stop shrinking where several are exactly or nearly
// equidistant (symmetric fans, concentric sites, near-flat skins): a cell with at most
// kSmallLeaf of them is enumerated as it is once they stayed the same over kStableLevels
// refinements or the cell is below kSmallLeafRadius. Subsets are enumerated once per
// solve, so a small leaf costs little when its neighbours share its sites; measured on
// the public meshes (1e-3 against 1e-1 and 1e-2: 20.6 and 21.3 us per near-flat fan
// against 20.1 for the whole-sphere subdivision).
constexpr int kSmallLeaf = 6;
constexpr int kStableLevels = 3;
constexpr double kSmallLeafRadius = 1e-3;

// Cells smaller than this (radians) are leaves whatever their sites: below the tie
// tolerance's scale of directions (kDistinctMaximizers = 1e-6), further refinement cannot
// separate maximisers that matter.
constexpr double kMinRadius = 1e-8;

// Closed cells (SiteSubdivision::close_cell): a cell below kCloseRadius with at most
// kCloseSites sites, of whose subsets at most kCloseMissing were not enumerated yet,
// enumerates those and is not refined. Along the ridges of near-ties of nearly flat
// fans such cells have 7 to 12 sites and miss up to a few dozen subsets; their leaves,
// hundreds of 5 or 6 sites each, would enumerate the same subsets again. Measured in
// instructions per solve on the 20 slowest fans of bench/normals/most_normal_tail_scan:
// the slowest went from 15.8 to 7.2 million; allowing 30 missing subsets left it at
// 11.3 million. Over the 5,000 fans of the scan's first seed the instructions fell by
// 0.8 %; closing at any radius raised them by 5 %. The check fails at the first subset
// beyond the allowance, at once in a region no leaf has reached.
constexpr int kCloseSites = 12;
constexpr double kCloseRadius = 1e-2;
constexpr int kCloseMissing = 60;
// The close check looks for the cell's sites among those of the last kRecentSets leaves
// and closed cells first: neighbours along a ridge share theirs.
constexpr int kRecentSets = 64;

// Under a binding visibility constraint, or in a cell that reaches below V_min, a fluid
// cell centre whose D exceeds the threshold by more than kProbeReach cell radii plus
// kProbeGain (radians) is offered as a floor (SiteSubdivision::probe_centre).
constexpr double kProbeReach = 2.0;
constexpr double kProbeGain = 1e-3;

// Allowance on every angle bound of a cell (D(c) + rho, V(c) + rho, the reach
// D(c) + 2 rho): D(c) is computed to ~1e-16 and rho to ~1e-16, so 1e-12 keeps every
// decision conservative by four orders.
constexpr double kBoundMargin = 1e-12;

// Allowance on the cosines and sines compared with those bounds (a few ulps of values
// <= 1).
constexpr double kTrigMargin = 1e-15;

// Allowance of the pair bound's cosine (SiteSubdivision::pair_bound_below): its dot and
// cross products of unit-length data, and cos(thr), are computed to a few ulps, so 1e-12
// keeps the comparison conservative by four orders.
constexpr double kPairMargin = 1e-12;

// The pair bound stops being tried after kPairTrials cells if it dropped fewer than one
// in kPairTriesPerDrop of them; from then on it is tried on one cell in
// kPairRetryInterval, and is back on every cell once its drops recover that rate. The
// ridge of a near-tie often lies deep in the refinement, after the first cells gave the
// bound up: on a valence-40 near-flat sliver fan the ridge then took 2,915 cells and
// 1.0 ms, with the retries 279 cells and 0.17 ms.
constexpr int kPairTrials = 64;
constexpr int kPairTriesPerDrop = 16;
constexpr int kPairRetryInterval = 8;

// Upper bound of the angle between unit vectors at chord t = |a - b|: the angle is
// 2 asin(t / 2) = t + t^3 / 24 + ..., below t + t^3 / 12 for t <= 1; the relative
// allowance covers the rounding of t.
double angle_from_chord(double t) {
  const double bound = t <= 1.0 ? t + t * t * t / 12.0 : 2.0 * std::asin(std::min(1.0, 0.5 * t));
  return bound * (1.0 + 1e-14);
}

// Cosine and sine bounds of an angle, conservative for "cos(angle) >= value" and
// "|x| <= sin(angle)" tests.
double cos_bound(double angle) { return angle >= M_PI ? -2.0 : std::cos(angle) - kTrigMargin; }
double sin_bound(double angle) { return angle >= 0.5 * M_PI ? 2.0 : std::sin(angle) + kTrigMargin; }

// fluid_side_at_vertex without arctangents, for cell centres (a disagreement with it
// exactly on the wedge boundary does not matter there: such a centre is within
// rounding of an arc, and its cell is never dropped for its side).
bool fluid_at_vertex(const FanGeometry& g, int j, const Vec3& n) {
  const auto [t_in, t_out, t_n, left] = vertex_tangents(g, j, n);
  // Counter-clockwise angle from t_out, compared by half-turn, then by orientation.
  const double sn = dot(left, t_n), cn = dot(t_out, t_n);
  const double si = dot(left, t_in), ci = dot(t_out, t_in);
  const int hn = sn < 0.0 ? 1 : 0, hi = si < 0.0 ? 1 : 0;
  if (hn != hi) return hn < hi;
  return cn * si - sn * ci > 0.0;
}

// Calls visit(sel, m) on every subset of one, two or three of the ids, in the order a,
// (a, b), (a, b, c) for a < b < c (the order fixes which candidate a tie keeps); stops
// and returns false as soon as visit does.
template <class Visit>
bool for_each_small_subset(const std::vector<int>& ids, Visit&& visit) {
  const int n = static_cast<int>(ids.size());
  for (int a = 0; a < n; ++a) {
    if (!visit(&ids[a], 1)) return false;
    for (int b = a + 1; b < n; ++b) {
      const int pair[2] = {ids[a], ids[b]};
      if (!visit(pair, 2)) return false;
      for (int c = b + 1; c < n; ++c) {
        const int triple[3] = {ids[a], ids[b], ids[c]};
        if (!visit(triple, 3)) return false;
      }
    }
  }
  return true;
}

// The subset's ids as first_time and subset_key take them (-1 for an absent one).
std::array<int, 3> padded(const int* sel, int m) { return {sel[0], m > 1 ? sel[1] : -1, m > 2 ? sel[2] : -1}; }

}  // namespace

SiteSubdivision::SiteSubdivision(const FanSites& sites, CandidatePool* pool)
    : s_(sites), pool_(*pool), g_(pool->geometry()), k_(pool->geometry().n_faces()) {
  lune1_.resize(k_);
  lune2_.resize(k_);
  for (int i = 0; i < k_; ++i) {
    lune1_[i] = arc_start_lune(g_, i);
    lune2_[i] = arc_end_lune(g_, i);
  }
  const int na = static_cast<int>(s_.arcs.size());
  merged_lune1_.resize(na);
  merged_lune2_.resize(na);
  for (int m = 0; m < na; ++m) {
    merged_lune1_[m] = normalized(cross(s_.arcs[m].g, s_.arcs[m].u));
    merged_lune2_[m] = normalized(cross(s_.arcs[m].v, s_.arcs[m].g));
  }
  arc_cos_.resize(k_);
  face_cos_.resize(k_);
  n_points_ = static_cast<int>(s_.points.size());
  vertex_stamp_.assign(g_.dirs.size(), 0);
  arc_stamp_.assign(na, 0);
}

SiteSubdivision::Cell SiteSubdivision::make_cell(int chart, double x0, double y0, double size) const {
  const Chart& ch = charts_[chart];
  auto direction = [&](double x, double y) { return normalized(ch.e0 + x * ch.e1 + y * ch.e2); };
  Cell cell{chart, x0, y0, size, direction(x0 + 0.5 * size, y0 + 0.5 * size), 0.0};
  // The cell is the central projection of a square, a convex spherical quadrangle within
  // 90 degrees of its centre, where the distance to the centre is convex: its farthest
  // points are corners.
  double chord = 0.0;
  for (double dx : {0.0, size})
    for (double dy : {0.0, size}) chord = std::max(chord, norm(cell.c - direction(x0 + dx, y0 + dy)));
  cell.rho = angle_from_chord(chord);
  return cell;
}

void SiteSubdivision::unconstrained_candidates() {
  charts_.clear();
  for (int face = 0; face < 6; ++face) {
    const int a = face % 3;
    const double sign = face < 3 ? 1.0 : -1.0;
    Chart ch{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    ch.e0[a] = sign;
    ch.e1[(a + 1) % 3] = 1.0;
    ch.e2[(a + 2) % 3] = 1.0;
    charts_.push_back(ch);
  }
  refine_roots();
}

void SiteSubdivision::constraint_leaves() {
  offer_subsets_ = false;
  unconstrained_candidates();
  offer_subsets_ = true;
}

void SiteSubdivision::unconstrained_candidates_near(const Vec3& centre, double radius) {
  Chart ch;
  ch.e0 = centre;
  orthonormal_complement(centre, &ch.e1, &ch.e2);
  charts_.assign(1, ch);
  // The square of half side tan(radius) holds the disc that is the cap's projection.
  const double t = std::tan(radius) * (1.0 + 1e-12);
  arena_.clear();
  for (int i = 0; i < k_; ++i) arena_.push_back(i);
  for (int i = 0; i < k_; ++i) arena_.push_back(i);
  refine(make_cell(0, -t, -t, 2.0 * t), 0, k_, k_, 2 * k_, 0, -1, 0);
}

void SiteSubdivision::refine_roots() {
  arena_.clear();
  for (int i = 0; i < k_; ++i) arena_.push_back(i);
  for (int i = 0; i < k_; ++i) arena_.push_back(i);
  for (int chart = 0; chart < static_cast<int>(charts_.size()); ++chart)
    refine(make_cell(chart, -1.0, -1.0, 2.0), 0, k_, k_, 2 * k_, 0, -1, 0);
}

void SiteSubdivision::refine(const Cell& cell, int arcs_begin, int arcs_end, int faces_begin, int faces_end,
                             int depth, int parent_sites, int stable_levels, bool invisible, int hint) {
  ++stats_.cells;
  stats_.max_depth = std::max(stats_.max_depth, depth);
  const Vec3& c = cell.c;
  const double rho = cell.rho;

  // The drop below (d_high under the threshold) taken from the hint alone: its distance
  // d_h bounds D(c), and d_h < reach = thr - rho - kBoundMargin when its cosine exceeds
  // cos(reach) by kTrigMargin, four orders above the rounding of either. On the CAD-like
  // ridge fans of valence 60 half the cells fall below the threshold (6,634 of 12,542);
  // those the hint catches skip the scan of all the kept arcs.
  if (hint >= 0) {
    const double reach = pool_.threshold() - rho - kBoundMargin;
    if (reach > 0.0 && reach < M_PI && arc_cosine(c, hint) > std::cos(reach) + kTrigMargin) {
      ++stats_.dropped_by_hint;
      return;
    }
  }

  // Distance from c to every arc the parent kept, as a cosine; the nearest one exactly.
  double best_cos = -3.0;
  int best = -1;
  for (int t = arcs_begin; t < arcs_end; ++t) {
    const int i = arena_[t];
    const double cs = arc_cosine(c, i);
    arc_cos_[i] = cs;
    if (cs > best_cos) {
      best_cos = cs;
      best = i;
    }
  }
  if (best < 0) return;
  const Vec3& f = g_.face_normals[best];
  const double cf = dot(c, f);
  const bool interior = dot(c, lune1_[best]) >= 0.0 && dot(c, lune2_[best]) >= 0.0;
  int vertex = -1;
  double d;
  if (interior) {
    d = std::atan2(std::fabs(cf), norm(c - cf * f));
  } else {
    const bool at_end = dot(c, g_.arc_end(best)) > dot(c, g_.arc_start(best));
    vertex = at_end ? next_vertex(best) : best;
    d = angle_between(c, g_.dirs[vertex]);
  }
  double v = 2.0;
  for (int t = faces_begin; t < faces_end; ++t) v = std::min(v, dot(c, g_.face_normals[arena_[t]]));

  const double d_high = d + rho + kBoundMargin;
  if (d_high < pool_.threshold()) return;
  // Feasible somewhere in the cell: face by face (V is 1-Lipschitz), and unless a pair of
  // faces rules it out (tried only where the centre fails V_min).
  bool maybe_feasible = !invisible;
  if (maybe_feasible && pool_.constrained())
    maybe_feasible = v + rho + kBoundMargin >= pool_.v_min() - kConstraintSlack &&
                     !(v < pool_.v_min() && pair_infeasible(c, rho, faces_begin, faces_end));
  if (!maybe_feasible) {
    // A cell invisible below V_min all over holds no candidate of the constraint circles
    // (docs/normals.md): when only those are sought, it is dropped whatever its D.
    if (!offer_subsets_ || d_high < pool_.unconstrained_threshold()) return;
    if (!refining_set_aside_ || pool_.limited()) {
      set_aside(cell, arcs_begin, arcs_end, faces_begin, faces_end, depth, parent_sites, stable_levels, d_high);
      return;
    }
  }
  if (d > rho + kBoundMargin) {
    // No arc meets the cap: the whole cell lies on the side of its centre.
    const bool fluid = interior ? cf > 0.0 : fluid_at_vertex(g_, vertex, c);
    if (!fluid) return;
    // Probed where the constrained optimum may lie on a constraint circle, whose
    // candidates come only after the refinement: under a binding constraint, and in a
    // cell that reaches below V_min (V is 1-Lipschitz, so v - rho bounds it there). A
    // centre below V_min on the kept faces is below it on all of them: not probed.
    const bool reaches_constraint = pool_.constrained() && v - rho - kBoundMargin < pool_.v_min();
    const bool centre_infeasible = pool_.constrained() && v < pool_.v_min();
    if ((pool_.limited() || reaches_constraint) && !centre_infeasible &&
        d - kProbeReach * rho > pool_.threshold() + kProbeGain)
      probe_centre(c);
  }

  const double cos_reach = cos_bound(d + 2.0 * rho + kBoundMargin);
  const int own_arcs = static_cast<int>(arena_.size());
  for (int t = arcs_begin; t < arcs_end; ++t)
    if (arc_cos_[arena_[t]] >= cos_reach) arena_.push_back(arena_[t]);
  const int own_faces = static_cast<int>(arena_.size());
  const double v_reach = v + 2.0 * rho + kBoundMargin;
  for (int t = faces_begin; t < faces_end; ++t)
    if (dot(c, g_.face_normals[arena_[t]]) <= v_reach) arena_.push_back(arena_[t]);
  const int own_end = static_cast<int>(arena_.size());
  gather_sites(c, rho, cos_reach, own_arcs, own_faces);
  // The pair bound is for ridges of near-ties, where many sites can be nearest; tried on
  // the children of cells with more than kSmallLeaf of them, it costs nothing elsewhere.
  if (parent_sites > kSmallLeaf && pair_bound_below(c, rho)) {
    arena_.resize(own_arcs);
    return;
  }
  const int n_sites = static_cast<int>(leaf_points_.size() + leaf_arcs_.size());
  const int stable = n_sites == parent_sites ? stable_levels + 1 : 0;
  if (n_sites <= kLeafSites || rho < kMinRadius || (n_sites <= kSmallLeaf && stable >= kStableLevels) ||
      (n_sites <= kSmallLeaf && rho < kSmallLeafRadius)) {
    record_leaf(cell, d, v, own_faces, own_end, !maybe_feasible);
    if (offer_subsets_) enumerate_new_subsets();
  } else if (offer_subsets_ && n_sites <= kCloseSites && rho < kCloseRadius &&
             v - rho - kBoundMargin > pool_.v_min() && close_cell()) {
    ++stats_.closed;
  } else {
    // Uphill first: D grows away from the nearest feature at c, so the children on that
    // side are refined first and their candidates raise the threshold for the others.
    // Without candidates (constraint_leaves) the order gains nothing.
    const Vec3 away = interior ? (cf >= 0.0 ? 1.0 : -1.0) * f : -g_.dirs[vertex];
    const double half = 0.5 * cell.size;
    Cell kids[4];
    double rank[4];
    int order[4] = {0, 1, 2, 3};
    for (int q = 0; q < 4; ++q)
      kids[q] = make_cell(cell.chart, cell.x0 + (q >> 1) * half, cell.y0 + (q & 1) * half, half);
    if (offer_subsets_) {
      for (int q = 0; q < 4; ++q) rank[q] = dot(kids[q].c, away);
      std::sort(order, order + 4, [&](int a, int b) { return rank[a] > rank[b]; });
    }
    for (int q : order)
      refine(kids[q], own_arcs, own_faces, own_faces, own_end, depth + 1, n_sites, stable, !maybe_feasible, best);
  }
  arena_.resize(own_arcs);
}

bool SiteSubdivision::pair_infeasible(const Vec3& c, double rho, int faces_begin, int faces_end) {
  // The two lowest faces at c, and every face's c.f for the pairs.
  int lowest[2] = {-1, -1};
  double low_cos[2] = {3.0, 3.0};
  for (int t = faces_begin; t < faces_end; ++t) {
    const int i = arena_[t];
    const double cf = dot(c, g_.face_normals[i]);
    face_cos_[i] = cf;
    if (cf < low_cos[0]) {
      lowest[1] = lowest[0], low_cos[1] = low_cos[0];
      lowest[0] = i, low_cos[0] = cf;
    } else if (cf < low_cos[1]) {
      lowest[1] = i, low_cos[1] = cf;
    }
  }
  const double level = 2.0 * (pool_.v_min() - kConstraintSlack);
  for (int q = 0; q < 2 && lowest[q] >= 0; ++q) {
    const int a = lowest[q];
    const Vec3& fa = g_.face_normals[a];
    // The bound of n.(f_a + f_b) on the cap is at least c.f_a + c.f_b.
    const double reach = level - low_cos[q];
    for (int t = faces_begin; t < faces_end; ++t) {
      const int b = arena_[t];
      if (b != a && face_cos_[b] < reach && pair_sum_below_on_cap(c, rho, fa, g_.face_normals[b], level)) return true;
    }
  }
  return false;
}

void SiteSubdivision::probe_centre(const Vec3& c) {
  if (pool_.constrained() && !(fan_visibility(g_, c) >= pool_.v_min())) return;
  double d;
  bool fluid;
  if (!pool_.evaluate(c, pool_.threshold(), &d, &fluid) || !fluid || !(d > pool_.floor())) return;
  if (!pool_.limited()) ++stats_.floors_raised_unlimited;
  pool_.raise_floor(c, d);
  ++stats_.floors_raised;
}

void SiteSubdivision::set_aside(const Cell& cell, int arcs_begin, int arcs_end, int faces_begin, int faces_end,
                                int depth, int parent_sites, int stable_levels, double d_high) {
  ++stats_.set_aside;
  set_aside_.push_back({cell, static_cast<int>(set_aside_ids_.size()), arcs_end - arcs_begin, faces_end - faces_begin,
                        depth, parent_sites, stable_levels, d_high});
  set_aside_ids_.insert(set_aside_ids_.end(), arena_.begin() + arcs_begin, arena_.begin() + arcs_end);
  set_aside_ids_.insert(set_aside_ids_.end(), arena_.begin() + faces_begin, arena_.begin() + faces_end);
}

bool SiteSubdivision::remaining_passes() {
  bool non_unique = false, plateaus_done = false, circles_done = false;
  auto plateaus = [&]() {
    non_unique = pool_.unconstrained_maxima_distinct() || pool_.constrained_maxima_distinct();
    if (non_unique) plateau_peaks();
    plateaus_done = true;
  };
  for (;;) {
    // A direction beyond the tie of the constrained optimum is known: the plateaus first
    // (their feasible part may reach it), then the constraint circles.
    if (!circles_done && pool_.limited()) {
      if (!plateaus_done) plateaus();
      if (pool_.limited()) {
        constraint_circles();
        circles_done = true;
      }
    }
    // The constrained optimum is final and some direction beats it: the status is settled.
    if (circles_done && pool_.limited()) break;
    if (set_aside_.empty()) break;
    refine_set_aside();
  }
  if (!plateaus_done) plateaus();
  if (!circles_done && pool_.limited()) constraint_circles();
  return non_unique;
}

void SiteSubdivision::refine_set_aside() {
  set_aside_batch_.clear();
  set_aside_batch_ids_.clear();
  set_aside_batch_.swap(set_aside_);
  set_aside_batch_ids_.swap(set_aside_ids_);
  // The cell that may reach the highest D first: the likeliest to show a direction beyond
  // the constrained optimum at once.
  std::sort(set_aside_batch_.begin(), set_aside_batch_.end(),
            [](const SetAside& a, const SetAside& b) { return a.d_high > b.d_high; });
  pool_.end_constrained_pass();
  refining_set_aside_ = true;
  for (const SetAside& cell : set_aside_batch_) {
    // refine() would find the cell's d_high again, from the same arcs, and drop it below
    // either threshold: both only rise, and the batch is sorted, so the first such cell
    // ends it (on a valence-30 sliver fan 2,361 set-aside cells were taken up again, all
    // but a handful to be dropped at once).
    if (cell.d_high < pool_.threshold() || cell.d_high < pool_.unconstrained_threshold()) break;
    arena_.assign(set_aside_batch_ids_.begin() + cell.ids_begin,
                  set_aside_batch_ids_.begin() + cell.ids_begin + cell.n_arcs + cell.n_faces);
    if (pool_.limited()) {
      // The status is settled: refine() would set the cell aside again as it is.
      set_aside(cell.cell, 0, cell.n_arcs, cell.n_arcs, cell.n_arcs + cell.n_faces, cell.depth, cell.parent_sites,
                cell.stable_levels, cell.d_high);
      continue;
    }
    ++stats_.set_aside_refined;
    refine(cell.cell, 0, cell.n_arcs, cell.n_arcs, cell.n_arcs + cell.n_faces, cell.depth, cell.parent_sites,
           cell.stable_levels, true);
  }
  refining_set_aside_ = false;
}

// The sites that can be nearest in a cell: reflex ends of the kept arcs within reach
// whose wedge meets the cap, and merged arcs whose foot-inside lune meets the cap. A
// generator s of a candidate that can still become a maximiser has d_s = D >= thr there,
// and an arc's interior is at arcsin|n.g| <= arcsin(|c.g| + rho) in the cell: arcs whose
// circle passes nearer cannot generate one (none can above 90 degrees). A link vertex w
// lies on both its arcs, so it is nearest only where it is the nearest point of each:
// where n's foot on the incoming arc's circle lies beyond w (n.lune2 <= 0) and its foot
// on the outgoing one's before w (n.lune1 <= 0). Elsewhere a foot inside an arc is
// nearer than w, and a foot past the arc's other end is nearer to that end: arcs are
// shorter than a half circle. At a nearly flat reflex junction this wedge is a thin
// band around the great circle through w across the arcs. The ends within reach,
// reflex or not, are kept in near_ for the pair bound.
void SiteSubdivision::gather_sites(const Vec3& c, double rho, double cos_reach, int arcs_begin, int arcs_end) {
  ++stamp_;
  near_.clear();
  leaf_points_.clear();
  leaf_arcs_.clear();
  const double lune_reach = -sin_bound(rho + kBoundMargin);
  const double wedge_reach = -lune_reach;
  const double thr = pool_.threshold() - kBoundMargin;
  const double arc_reach = thr <= 0.0 ? -1.0 : (thr > 0.5 * M_PI ? 3.0 : std::sin(thr) - rho - kBoundMargin);
  for (int t = arcs_begin; t < arcs_end; ++t) {
    const int i = arena_[t];
    for (int j : {i, next_vertex(i)}) {
      if (vertex_stamp_[j] == stamp_) continue;
      vertex_stamp_[j] = stamp_;
      const double cu = dot(c, g_.dirs[j]);
      if (!(cu >= cos_reach)) continue;
      near_.push_back({cu, j});
      if (s_.point_of_vertex[j] >= 0 && dot(c, lune2_[previous_vertex(j)]) <= wedge_reach &&
          dot(c, lune1_[j]) <= wedge_reach)
        leaf_points_.push_back(s_.point_of_vertex[j]);
    }
    const int m = s_.arc_of_face[i];
    if (arc_stamp_[m] == stamp_) continue;
    arc_stamp_[m] = stamp_;
    if (dot(c, merged_lune1_[m]) >= lune_reach && dot(c, merged_lune2_[m]) >= lune_reach &&
        std::fabs(dot(c, s_.arcs[m].g)) >= arc_reach)
      leaf_arcs_.push_back(m);
  }
}

bool SiteSubdivision::pair_bound_below(const Vec3& c, double rho) {
  const double thr = pool_.threshold();
  if (!(thr > 0.0) || thr > M_PI || rho >= 0.5 * M_PI) return false;
  // Where no near-antipodal pair shapes the optimum the bound never prunes and only costs
  // its pairs: after kPairTrials cells with less than one drop in kPairTriesPerDrop, it is
  // tried only on one cell in kPairRetryInterval (a pure cost decision: dropping fewer
  // cells is exact).
  if (pair_tries_ >= kPairTrials && pair_drops_ * kPairTriesPerDrop < pair_tries_ &&
      ++pair_skips_ % kPairRetryInterval != 0)
    return false;
  ++pair_tries_;
  const double cr = std::cos(rho), sr = std::sin(rho);
  const double level = std::cos(thr) + kPairMargin;
  // The bound's cosine is at most c.q cos(rho) = (c.u_a + c.u_b) cos(rho) / 2: with the
  // vertices by decreasing c.u, each a's partners stop at the first b below that. A
  // vertex whose c.u falls short of that even beside the largest pairs with none, so
  // only the others are sorted (they are the same pairs, in the same order).
  const double pair_sum = 2.0 * level / cr;
  double largest = -2.0;
  for (const auto& entry : near_) largest = std::max(largest, entry.first);
  near_.erase(std::remove_if(near_.begin(), near_.end(),
                             [&](const auto& entry) { return !(entry.first + largest > pair_sum); }),
              near_.end());
  std::sort(near_.begin(), near_.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  const int n = static_cast<int>(near_.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n && near_[a].first + near_[b].first > pair_sum; ++b) {
      const Vec3& u_a = g_.dirs[near_[a].second];
      const Vec3& u_b = g_.dirs[near_[b].second];
      // Most pairs fail, and are screened out without a root.
      if (pair_cap_certainly_below(0.5 * (near_[a].first + near_[b].first), cr, sr, u_a, u_b, level)) continue;
      if (pair_cap_cosine(c, cr, sr, u_a, u_b) > level) {
        ++pair_drops_;
        return true;
      }
    }
  return false;
}

bool SiteSubdivision::close_cell() {
  thread_local std::vector<int> ids;
  thread_local std::vector<std::array<int, 3>> missing;
  cell_site_ids(&ids);
  missing.clear();
  SiteSet set;
  const bool as_set = site_set(ids, &set);
  // Within a set whose subsets were all enumerated, none is missing; otherwise each is
  // looked up.
  if (!(as_set && within_enumerated_set(set)) && !missing_subsets(ids, &missing)) return false;
  thread_local std::vector<PlateauCircle> circles;
  circles.clear();
  const SiteSubset sub{leaf_points_.data(), static_cast<int>(leaf_points_.size()), leaf_arcs_.data(),
                       static_cast<int>(leaf_arcs_.size())};
  plateau_circles(s_, sub, pool_.tolerances().normality_tie, pool_.best_constrained(), &circles);
  if (!circles.empty()) return false;
  for (const std::array<int, 3>& m : missing) {
    first_time(m[0], m[1], m[2]);
    offer_subset(m.data(), m[1] < 0 ? 1 : (m[2] < 0 ? 2 : 3));
  }
  if (as_set) enumerated_sets_.push_back(set);
  return true;
}

bool SiteSubdivision::missing_subsets(const std::vector<int>& ids, std::vector<std::array<int, 3>>* missing) const {
  // Each subset is enumerated, or noted as missing within the allowance.
  return for_each_small_subset(ids, [&](const int* sel, int m) {
    const std::array<int, 3> k = padded(sel, m);
    if (enumerated(subset_key(k[0], k[1], k[2]))) return true;
    missing->push_back(k);
    return static_cast<int>(missing->size()) <= kCloseMissing;
  });
}

bool SiteSubdivision::site_set(const std::vector<int>& ids, SiteSet* set) {
  *set = {0, 0};
  for (int id : ids) {
    if (id >= 128) return false;
    (*set)[id >> 6] |= std::uint64_t(1) << (id & 63);
  }
  return true;
}

bool SiteSubdivision::within_enumerated_set(const SiteSet& set) const {
  const int n = static_cast<int>(enumerated_sets_.size());
  for (int t = n - 1; t >= std::max(0, n - kRecentSets); --t) {
    const SiteSet& m = enumerated_sets_[t];
    if ((set[0] & ~m[0]) == 0 && (set[1] & ~m[1]) == 0) return true;
  }
  return false;
}

// Site ids: points 0 .. n_points_ - 1, then merged arcs.
std::uint64_t SiteSubdivision::subset_key(int a, int b, int c) {
  // The sorted ids (-1 marks an absent one).
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a + 1) << 42) | (std::uint64_t(b + 1) << 21) | std::uint64_t(c + 1);
}

std::size_t SiteSubdivision::subset_hash(std::uint64_t key) { return (key * 0x9E3779B97F4A7C15ull) >> 20; }

bool SiteSubdivision::enumerated(std::uint64_t key) const {
  if (subset_table_.empty()) return false;
  const std::size_t mask = subset_table_.size() - 1;
  for (std::size_t h = subset_hash(key);; ++h) {
    const std::uint64_t slot = subset_table_[h & mask];
    if (slot == key) return true;
    if (slot == 0) return false;
  }
}

bool SiteSubdivision::first_time(int a, int b, int c) {
  // An open-addressing table of the subsets' keys.
  const std::uint64_t key = subset_key(a, b, c);
  if (2 * (subset_count_ + 1) > subset_table_.size()) {
    if (subset_table_.empty()) {
      // The first table of a solve, in the recycled buffer when there is one.
      subset_table_.assign(64, 0);
      return insert_subset(key);
    }
    std::vector<std::uint64_t> old(subset_table_.size() * 2, 0);
    old.swap(subset_table_);
    subset_count_ = 0;
    for (std::uint64_t k : old)
      if (k != 0) insert_subset(k);
  }
  return insert_subset(key);
}

bool SiteSubdivision::insert_subset(std::uint64_t key) {
  const std::size_t mask = subset_table_.size() - 1;
  for (std::size_t h = subset_hash(key);; ++h) {
    std::uint64_t& slot = subset_table_[h & mask];
    if (slot == key) return false;
    if (slot == 0) {
      slot = key;
      ++subset_count_;
      return true;
    }
  }
}

void SiteSubdivision::offer_subset(const int* sel, int m) {
  int pts[3], arcs[3];
  int np = 0, na = 0;
  for (int t = 0; t < m; ++t) {
    if (sel[t] < n_points_) {
      pts[np++] = sel[t];
    } else {
      arcs[na++] = sel[t] - n_points_;
    }
  }
  const SiteSubset sub{pts, np, arcs, na};
  const ArcReachScreen screen(pool_);
  auto emit = [&](const Vec3& x) { offer_anywhere(x); };
  if (m <= 2) {
    pair_candidates(s_, sub, screen, emit);
  } else {
    triple_candidates(s_, sub, screen, emit);
  }
}

void SiteSubdivision::cell_site_ids(std::vector<int>* ids) const {
  ids->clear();
  for (int p : leaf_points_) ids->push_back(p);
  for (int m : leaf_arcs_) ids->push_back(n_points_ + m);
}

// Offers the candidates of every single site, pair and triple of the current cell's
// sites not enumerated before, wherever they lie (evaluating a candidate outside the
// cell costs less than building it twice).
void SiteSubdivision::enumerate_new_subsets() {
  thread_local std::vector<int> ids;
  cell_site_ids(&ids);
  for_each_small_subset(ids, [&](const int* sel, int m) {
    const std::array<int, 3> k = padded(sel, m);
    if (first_time(k[0], k[1], k[2])) offer_subset(sel, m);
    return true;
  });
  SiteSet set;
  if (site_set(ids, &set)) enumerated_sets_.push_back(set);
}

void SiteSubdivision::record_leaf(const Cell& cell, double d, double v, int faces_begin, int faces_end,
                                  bool invisible) {
  // An invisible leaf keeps a V bound below any V_min, so that no pass takes it for a
  // feasible one (leaf_alive).
  const double v_bound = invisible ? -std::numeric_limits<double>::infinity() : v;
  Leaf leaf{cell.c, cell.rho, d, v_bound, static_cast<int>(leaf_ids_.size()), 0, 0,
            static_cast<int>(leaf_points_.size()), static_cast<int>(leaf_arcs_.size()), faces_end - faces_begin,
            cos_bound(cell.rho + kBoundMargin)};
  leaf_ids_.insert(leaf_ids_.end(), leaf_points_.begin(), leaf_points_.end());
  leaf.arcs_begin = static_cast<int>(leaf_ids_.size());
  leaf_ids_.insert(leaf_ids_.end(), leaf_arcs_.begin(), leaf_arcs_.end());
  leaf.faces_begin = static_cast<int>(leaf_ids_.size());
  leaf_ids_.insert(leaf_ids_.end(), arena_.begin() + faces_begin, arena_.begin() + faces_end);
  leaves_.push_back(leaf);
  ++stats_.leaves;
}

// Offers candidate n (unnormalised) if it lies in the leaf and was not offered before.
void SiteSubdivision::offer(const Leaf& leaf, const Vec3& n) {
  const double len = norm(n);
  if (!(len > 0.0) || !std::isfinite(len)) return;
  if (dot(n, leaf.c) < leaf.cos_cap * len) return;
  offer_anywhere(n);
}

// Offers candidate n (unnormalised) wherever it lies.
void SiteSubdivision::offer_anywhere(const Vec3& n) { pool_.consider(n); }

SiteSubset SiteSubdivision::subset(const Leaf& leaf) const {
  return {leaf_ids_.data() + leaf.points_begin, leaf.n_points, leaf_ids_.data() + leaf.arcs_begin, leaf.n_arcs};
}

bool SiteSubdivision::leaf_alive(const Leaf& leaf, bool feasible_only) const {
  const double d_high = leaf.d + leaf.rho + kBoundMargin;
  if (d_high < pool_.threshold()) return false;
  const bool maybe_feasible =
      !pool_.constrained() || leaf.v + leaf.rho + kBoundMargin >= pool_.v_min() - kConstraintSlack;
  if (feasible_only) return maybe_feasible;
  return maybe_feasible || d_high >= pool_.unconstrained_threshold();
}

void SiteSubdivision::plateau_peaks() {
  const double tie = pool_.tolerances().normality_tie;
  const double d_best = pool_.best_constrained();
  std::vector<PlateauCircle> circles;
  std::vector<double> ca, cb, cc;
  std::vector<int> faces;
  for (const Leaf& leaf : leaves_) {
    if (!leaf_alive(leaf, false)) continue;
    circles.clear();
    plateau_circles(s_, subset(leaf), tie, d_best, &circles);
    if (circles.empty()) continue;
    faces.assign(leaf_ids_.data() + leaf.faces_begin, leaf_ids_.data() + leaf.faces_begin + leaf.n_faces);
    one_face_per_plane(&faces);
    auto emit = [&](const Vec3& n) { offer(leaf, n); };
    for (const PlateauCircle& circ : circles) {
      if (std::fabs(dot(leaf.c, circ.h) - circ.c0) > leaf.rho + kBoundMargin) continue;
      plateau_envelope_peaks(g_, circ, faces.data(), static_cast<int>(faces.size()), leaf.c, leaf.cos_cap, &ca, &cb,
                             &cc, emit);
    }
  }
}

bool SiteSubdivision::planes_repeat() {
  if (same_plane_.empty()) {
    same_plane_runs(g_, &same_plane_);
    for (int j = 0; j < k_; ++j) planes_repeat_ = planes_repeat_ || same_plane_[j] != j;
  }
  return planes_repeat_;
}

void SiteSubdivision::one_face_per_plane(std::vector<int>* faces) {
  if (planes_repeat()) drop_repeated_planes(same_plane_, faces);
}

// A face whose visibility exceeds another's by more than the feasibility slack all over
// the leaf has its constraint circle there where the other face is infeasible: every
// candidate on it would be dropped by the constrained pass (CandidatePool::consider).
// Faces of a fan-triangulated CAD face have nearly parallel normals, and their circles
// cross the same leaves; the face below the others all over a leaf is often not the
// lowest at its centre (on a valence-40 sliver fan the lowest at the centre dropped none
// of 38 circles in 16 leaves, the three lowest all but two). A candidate that the
// rounding of two nearly parallel circles put off its circle goes with it: the only
// candidates dropped that could have been kept, and then only as ties.
void SiteSubdivision::drop_circles_below_another(const Leaf& leaf, std::vector<int>* crossing) {
  // The directions offer() lets into the leaf: n.c >= cos_cap |n|.
  const double c = leaf.cos_cap;
  if (crossing->empty() || !pool_.constrained() || !(c > 0.0)) return;
  // 4e-16 covers the rounding of 1 - c^2 (c^2 rounds by at most 1.2e-16), so that s
  // is never below the sine of the admitted radius.
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c) + 4e-16);
  // The leaf's faces by visibility at its centre, lowest first: a face lies below face i
  // all over the leaf only if it does at the centre by more than the slack
  // (cap_min_dot <= c.(f_i - f_l)), so the search for one stops there.
  // Only the first face of each plane's run (same_plane_runs) is a candidate below: a
  // face left out only keeps circles that it would have dropped.
  const bool repeat = planes_repeat();
  by_visibility_.clear();
  for (int t = 0; t < leaf.n_faces; ++t) {
    const int l = leaf_ids_[leaf.faces_begin + t];
    if (repeat && same_plane_[l] != l) continue;
    by_visibility_.push_back({dot(leaf.c, g_.face_normals[l]), l});
  }
  std::sort(by_visibility_.begin(), by_visibility_.end());
  auto dominated = [&](int i) {
    const Vec3& fi = g_.face_normals[i];
    const double vi = dot(leaf.c, fi);
    for (const auto& [vl, l] : by_visibility_) {
      if (!(vl < vi - kConstraintSlack)) return false;
      const Vec3 delta = fi - g_.face_normals[l];
      if (dot(leaf.c, delta) > 0.0 && cap_min_dot(leaf.c, c, s, delta) > kConstraintSlack + kBoundMargin) return true;
    }
    return false;
  };
  crossing->erase(std::remove_if(crossing->begin(), crossing->end(), dominated), crossing->end());
}

namespace {

// Faces within about 25 degrees of a constraint circle's face (normals' cosine above
// this) do not cut that circle's cone window. Any subset of the faces gives a valid
// window; such a face keeps about half of the circle, which cuts little from a leaf's
// arc, and fan-triangulated faces cross a leaf with dozens of such circles (their
// trigonometry cost the sliver wing a fifth of its most-normal solves).
constexpr double kWindowFaceCos = 0.9;

// The constraint pass's region in a leaf: the directions offer() admits,
// n.c >= cos_cap |n|, where the leaf's faces whose constraint circles cross it keep them
// feasible (the other faces are feasible on all of the leaf; the crossing faces dropped
// by drop_circles_below_another are feasible wherever the face below them is).
// Intersections on great circles that pass outside the leaf would not be offered: they
// are not built (a valence-40 sliver fan's 16,000 face pairs in 51 leaves). Nor are the
// quartics of point-arc cones solved where their roots cannot fall in the window of the
// constraint circle that is in the leaf and feasible (on a valence-40 sliver fan 1,404
// quartics took 60 % of a 2.5 ms solve, for 15 candidates in their leaves).
struct LeafRegion {
  const FanGeometry& g;
  Vec3 c;
  double cos_cap;
  const std::vector<int>& crossing;
  double v_min;
  bool great_circle(const Vec3& h) const { return great_circle_meets_cap(c, cos_cap, h); }
  CircleWindow window(const Vec3& h, double c0) const {
    CircleWindow w = circle_window_in_cap(c, cos_cap, h, c0);
    for (int j : crossing) {
      if (w.half_width < 0.0) break;
      const Vec3& f = g.face_normals[j];
      if (dot(f, h) < kWindowFaceCos) w = intersect_windows(w, circle_window_feasible(f, v_min, h, c0));
    }
    return w;
  }
};

}  // namespace

void SiteSubdivision::constraint_circles() {
  pool_.begin_constrained_pass();
  const double v_min = pool_.v_min();
  std::vector<int> crossing;
  for (const Leaf& leaf : leaves_) {
    if (!leaf_alive(leaf, true)) continue;
    crossing.clear();
    for (int t = 0; t < leaf.n_faces; ++t) {
      const int i = leaf_ids_[leaf.faces_begin + t];
      if (std::fabs(dot(leaf.c, g_.face_normals[i]) - v_min) <= leaf.rho + kBoundMargin) crossing.push_back(i);
    }
    one_face_per_plane(&crossing);
    drop_circles_below_another(leaf, &crossing);
    if (crossing.empty()) continue;
    auto emit = [&](const Vec3& n) { offer(leaf, n); };
    constraint_candidates(g_, s_, subset(leaf), crossing.data(), static_cast<int>(crossing.size()), v_min, emit,
                          LeafRegion{g_, leaf.c, leaf.cos_cap, crossing, v_min});
  }
}

}  // namespace detail
}  // namespace blayer
