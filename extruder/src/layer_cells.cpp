#include "blayer/extruder/layer_cells.h"


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

}  // namespace blayer
