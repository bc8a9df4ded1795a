#include "blayer/extruder/layer_cells.h"

#include "blayer/quality/cell_validity.h"
#include "blayer/quality/quad_cap.h"

namespace blayer {

bool layer_cell(const std::array<std::int64_t, 3>& bottom, const std::array<std::int64_t, 3>& top,
                const std::array<bool, 3>& grows, LayerCell* out) {
  const int n_grow = int(grows[0]) + int(grows[1]) + int(grows[2]);
  if (n_grow == 3) {
    out->type = CellType::kWedge;
    out->nodes = {bottom[0], bottom[2], bottom[1], top[0], top[2], top[1]};
    return true;
  }
  if (n_grow == 2) {
    const int x = !grows[0] ? 0 : (!grows[1] ? 1 : 2);
    const int y = (x + 1) % 3, z = (x + 2) % 3;
    out->type = CellType::kPyramid;
    out->nodes = {bottom[y], top[y], top[z], bottom[z], bottom[x], 0};
    return true;
  }
  if (n_grow == 1) {
    const int z = grows[0] ? 0 : (grows[1] ? 1 : 2);
    const int x = (z + 1) % 3, y = (z + 2) % 3;
    out->type = CellType::kTet;
    out->nodes = {bottom[x], bottom[y], bottom[z], top[z], 0, 0};
    return true;
  }
  return false;
}

namespace {

// Strip (q0 q1 q2 q3) whose first fan point (q0 q1) grows and whose second (q2 q3) is
// stopped.
void strip_closure(const std::array<std::int64_t, 4>& b, const std::array<std::int64_t, 4>& t, LayerCell* out) {
  if (b[0] == b[1]) {
    out->type = CellType::kTet;
    out->nodes = {b[0], t[0], t[1], b[2], 0, 0};
  } else {
    out->type = CellType::kWedge;
    out->nodes = {b[1], b[2], t[1], b[0], b[3], t[0]};
  }
}

void tet(LayerCell* out, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  out->type = CellType::kTet;
  out->nodes = {a, b, c, d, 0, 0};
}

// The pyramid (n0 .. n4) as two tets, its base split along the diagonal n0-n2
// (along_02) or n1-n3.
int split_pyramid(const LayerCell& pyr, bool along_02, LayerCell* out) {
  const auto& n = pyr.nodes;
  if (along_02) {
    tet(&out[0], n[0], n[1], n[2], n[4]);
    tet(&out[1], n[0], n[2], n[3], n[4]);
  } else {
    tet(&out[0], n[0], n[1], n[3], n[4]);
    tet(&out[1], n[1], n[2], n[3], n[4]);
  }
  return 2;
}

// A layer of a triangle (P, Y, Z) whose column P ends a ridge: every side face at P is
// split along the diagonal from P's base to the other column's top (as the strip ends
// beside it are), so that those faces, twisted between P's direction and a fan's, are
// no quads.
int split_at_ridge_end(const std::array<std::int64_t, 3>& b, const std::array<std::int64_t, 3>& t,
                       const std::array<bool, 3>& g, LayerCell* out) {
  const std::int64_t p = b[0], y = b[1], z = b[2];
  if (!g[0] || (!g[1] && !g[2])) {  // the closure already has triangles there
    return layer_cell(b, t, g, out) ? 1 : 0;
  }
  if (g[1] && g[2]) {  // wedge = pyramid on the far quad + the tet under the top
    out[0].type = CellType::kPyramid;
    out[0].nodes = {y, t[1], t[2], z, p, 0};
    tet(&out[1], t[0], t[2], t[1], p);
    return 2;
  }
  LayerCell pyr;
  layer_cell(b, t, g, &pyr);
  // Z stopped: pyramid (p, p', y', y, z), split along p-y'; Y stopped: pyramid
  // (z, z', p', p, y), split along z'-p.
  return split_pyramid(pyr, !g[2], out);
}

}  // namespace

int element_layer_cells(const LayerElement& e, const std::array<std::int64_t, 4>& bottom,
                        const std::array<std::int64_t, 4>& top, const std::array<bool, 4>& grows, LayerCell* out) {
  if (e.kind == ElementKind::kStripEnd && bottom[1] == bottom[2]) {
    // (P, X, Y) on the wall: p = bottom[0], q = bottom[1] the fan point; its side faces
    // at P are split along p-X' and p-Y'.
    const std::int64_t p = bottom[0], q = bottom[1];
    if (!grows[1]) return 0;
    tet(&out[0], q, top[1], top[2], p);
    if (!grows[0]) return 1;
    tet(&out[1], top[0], top[2], top[1], p);
    return 2;
  }
  if (e.kind == ElementKind::kStripEnd)
    return split_at_ridge_end({bottom[0], bottom[1], bottom[2]}, {top[0], top[1], top[2]},
                              {grows[0], grows[1], grows[2]}, out);
  if (e.kind != ElementKind::kStrip) {
    const std::array<std::int64_t, 3> b{bottom[0], bottom[1], bottom[2]}, t{top[0], top[1], top[2]};
    const std::array<bool, 3> g{grows[0], grows[1], grows[2]};
    if (b[0] == b[1] && b[1] == b[2]) {
      if (!g[0]) return 0;
      tet(out, t[0], t[2], t[1], b[0]);
      return 1;
    }
    if (e.split_at >= 0) {
      const int i = e.split_at, j = (i + 1) % 3, k = (i + 2) % 3;
      return split_at_ridge_end({b[i], b[j], b[k]}, {t[i], t[j], t[k]}, {g[i], g[j], g[k]}, out);
    }
    return layer_cell(b, t, g, out) ? 1 : 0;
  }
  const bool gx = grows[0], gy = grows[2];
  if (gx && gy) {
    if (bottom[0] == bottom[1]) {
      out->type = CellType::kWedge;
      out->nodes = {bottom[0], top[1], top[0], bottom[2], top[2], top[3]};
    } else {
      out->type = CellType::kHex;
      std::copy(bottom.begin(), bottom.end(), out->nodes.begin());
      out->nodes[4] = top[0];
      out->nodes[5] = top[1];
      out->nodes[6] = top[2];
      out->nodes[7] = top[3];
    }
    return 1;
  }
  if (gx) {
    strip_closure(bottom, top, out);
    return 1;
  }
  if (gy) {
    strip_closure({bottom[2], bottom[3], bottom[0], bottom[1]}, {top[2], top[3], top[0], top[1]}, out);
    return 1;
  }
  return 0;
}

bool layer_cell_accepted(const LayerElement& e, const LayerCell& cell, const Vec3* corners) {
  if (!cell_is_valid(cell.type, corners)) return false;
  if (e.kind != ElementKind::kStrip) return true;
  if (cell.type == CellType::kHex) return quad_cap_apex({corners[4], corners[5], corners[6], corners[7]}).has_value();
  if (cell.type == CellType::kWedge) return quad_cap_apex({corners[1], corners[4], corners[5], corners[2]}).has_value();
  return true;
}

}  // namespace blayer
