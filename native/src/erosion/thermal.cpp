// Thermal erosion (Musgrave, Kolb & Mace 1989): where the drop to a
// neighbour exceeds the talus slope, material slides down. Each pass every
// cell works out, from the previous heights, how much it sends: `rate` x
// half its largest excess drop (half: moving more would turn the step the
// other way), shared among the lower neighbours in proportion to their
// excess. The receivers then gather what their neighbours send, so the pass
// is Jacobi-ordered (thread-count independent) and conserves material to
// rounding; nothing crosses a bounded edge. (talus[k] is the same in both
// directions of a pair, so one table serves sender and receiver.)
#include <algorithm>
#include <cmath>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {
namespace {

// Neighbour k of cell i = (x, y): at a fixed offset inside the grid, by the
// general lookup (-1 outside a bounded grid) on its first and last rows and
// columns. The interior loops then have no edge tests and vectorise.
template <class Cell>
void each_cell(const D8Grid& g, int32_t y, Cell&& cell) {
  const int32_t w = g.width;
  const int64_t row = int64_t(y) * w;
  auto general = [&](int32_t x) {
    int64_t j[8];
    for (int k = 0; k < 8; ++k) j[k] = g.neighbour(x, y, k);
    cell.template operator()<false>(row + x, j);
  };
  if (y == 0 || y == g.height - 1) {
    for (int32_t x = 0; x < w; ++x) general(x);
    return;
  }
  general(0);
  int64_t off[8];
  for (int k = 0; k < 8; ++k) off[k] = kDy[k] * int64_t(w) + kDx[k];
  for (int32_t x = 1; x < w - 1; ++x) {
    const int64_t i = row + x;
    int64_t j[8];
    for (int k = 0; k < 8; ++k) j[k] = i + off[k];
    cell.template operator()<true>(i, j);
  }
  general(w - 1);
}

}  // namespace

void thermal(const D8Grid& g, float* z, const ThermalConfig& c, const Progress& progress) {
  const size_t n = g.size();
  const int32_t h = g.height;
  float talus[8];
  for (int k = 0; k < 8; ++k) talus[k] = float(std::tan(c.talus_degrees * M_PI / 180.0) * g.distance(k));
  const float half_rate = float(c.rate) * 0.5f;
  // share[i]: what cell i sends per unit of excess drop (0: nothing).
  std::vector<float> share(n), next(n);
  for (int32_t it = 0; it < c.iterations; ++it) {
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      each_cell(g, y, [&]<bool Interior>(int64_t i, const int64_t* j) {
        float total = 0.0f, largest = 0.0f;
        for (int k = 0; k < 8; ++k) {
          if (!Interior && j[k] < 0) continue;
          const float excess = std::max(0.0f, z[i] - z[j[k]] - talus[k]);
          total += excess;
          largest = std::max(largest, excess);
        }
        share[i] = total > 0.0f ? half_rate * largest / total : 0.0f;
      });
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      each_cell(g, y, [&]<bool Interior>(int64_t i, const int64_t* j) {
        float sent = 0.0f, received = 0.0f;
        for (int k = 0; k < 8; ++k) {
          if (!Interior && j[k] < 0) continue;
          sent += std::max(0.0f, z[i] - z[j[k]] - talus[k]);
          received += share[j[k]] * std::max(0.0f, z[j[k]] - z[i] - talus[k]);
        }
        next[i] = z[i] - share[i] * sent + received;
      });
    std::copy(next.begin(), next.end(), z);
    progress.report(double(it + 1) / c.iterations);
  }
}

}  // namespace ft::erosion
