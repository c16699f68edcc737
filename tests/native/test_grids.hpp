// SPDX-License-Identifier: GPL-3.0-or-later
// Grid helpers several native test files measure with, written once.
#pragma once

#include <cstdint>
#include <vector>

namespace ft::test {

// The fine grid averaged over each coarse cell (factor f, centred on the
// coarse node, clamped at the edges).
inline std::vector<float> downsample(const std::vector<float>& v, int32_t w, int32_t f) {
  const int32_t wc = (w - 1) / f + 1;
  std::vector<float> out(size_t(wc) * wc);
  for (int32_t y = 0; y < wc; ++y)
    for (int32_t x = 0; x < wc; ++x) {
      double s = 0;
      int n = 0;
      for (int32_t dy = -f / 2; dy <= f / 2; ++dy)
        for (int32_t dx = -f / 2; dx <= f / 2; ++dx) {
          const int32_t fx = x * f + dx, fy = y * f + dy;
          if (fx < 0 || fy < 0 || fx >= w || fy >= w) continue;
          s += v[size_t(fy) * w + fx];
          ++n;
        }
      out[size_t(y) * wc + x] = float(s / n);
    }
  return out;
}

}  // namespace ft::test
