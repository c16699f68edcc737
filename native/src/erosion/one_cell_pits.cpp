// SPDX-License-Identifier: GPL-3.0-or-later
// One-cell pits lifted (see one_cell_pits.hpp).
#include "erosion/one_cell_pits.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ft::erosion {

float one_cell_pit_lifted(float z, const float (&neighbours)[8], float erodible) {
  const float lowest = *std::min_element(std::begin(neighbours), std::end(neighbours));
  if (!(z < lowest) || !(erodible > 0)) return z;
  // To the lowest's height, not a float step above it: the lowest may
  // drain only through this sample, and would then become the pit.
  return erodible >= 1 ? lowest : float(z + double(erodible) * (double(lowest) - z));
}

void lift_one_cell_pits(float* z, int32_t w, int32_t h, bool periodic, const uint8_t* stays, const float* mask) {
  if (w < 3 || h < 3) return;
  const std::vector<float> was(z, z + size_t(w) * h);
  const int32_t first = periodic ? 0 : 1;
#pragma omp parallel for schedule(static)
  for (int32_t y = first; y < h - first; ++y)
    for (int32_t x = first; x < w - first; ++x) {
      const size_t i = size_t(y) * w + x;
      if (stays && stays[i]) continue;
      float nb[8];
      int k = 0;
      for (int32_t dy = -1; dy <= 1; ++dy)
        for (int32_t dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) continue;
          const int32_t nx = (x + dx + w) % w, ny = (y + dy + h) % h;  // inside a bounded grid's edges anyway
          nb[k++] = was[size_t(ny) * w + nx];
        }
      z[i] = one_cell_pit_lifted(was[i], nb, mask ? mask[i] : 1.0f);
    }
}

}  // namespace ft::erosion
