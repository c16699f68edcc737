// SPDX-License-Identifier: GPL-3.0-or-later
// The sea (see sea.hpp): a flood from the map's edge through the cells at or
// below its level.
#include "erosion/sea.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ft::erosion {

double sea_height(Sea sea, double level, double fraction, const Heightfield& hf) {
  if (sea == Sea::kNone || hf.size() == 0) return std::numeric_limits<double>::quiet_NaN();
  if (sea == Sea::kHeight) return level;
  std::vector<float> z(hf.data(), hf.data() + hf.size());
  const size_t k = std::min(z.size() - 1, size_t(fraction * double(z.size())));
  std::nth_element(z.begin(), z.begin() + std::ptrdiff_t(k), z.end());
  return double(z[k]);
}

std::vector<uint8_t> sea_cells(const D8Grid& g, const float* z, double level) {
  const size_t n = g.size();
  std::vector<uint8_t> sea(n, 0);
  if (!std::isfinite(level)) return sea;
  auto wet = [&](size_t i) { return in_sea(z[i], level); };
  std::vector<int32_t> todo;
  auto seed = [&](size_t i) {
    if (!sea[i] && wet(i)) {
      sea[i] = 1;
      todo.push_back(int32_t(i));
    }
  };
  if (g.periodic) {
    seed(size_t(std::min_element(z, z + n) - z));
  } else {
    for (int32_t x = 0; x < g.width; ++x) seed(size_t(x)), seed(size_t(g.height - 1) * g.width + x);
    for (int32_t y = 0; y < g.height; ++y) seed(size_t(y) * g.width), seed(size_t(y) * g.width + g.width - 1);
  }
  while (!todo.empty()) {
    const int32_t c = todo.back();
    todo.pop_back();
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(c % g.width, c / g.width, k);
      if (j >= 0) seed(size_t(j));
    }
  }
  return sea;
}

}  // namespace ft::erosion
