// Thermal erosion (Musgrave, Kolb & Mace 1989): where the drop to a
// neighbour exceeds the talus slope, material slides down. Each pass every
// cell works out, from the previous heights, how much it sends: `rate` x
// half its largest excess drop (half: moving more would turn the step the
// other way), shared among the lower neighbours in proportion to their
// excess. The receivers then gather what their neighbours send, so the pass
// is Jacobi-ordered (thread-count independent) and conserves material to
// rounding; nothing crosses a bounded edge.
#include <algorithm>
#include <cmath>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {

void thermal(const D8Grid& g, float* z, const ThermalConfig& c, const Progress& progress) {
  const size_t n = g.size();
  const int32_t w = g.width, h = g.height;
  float talus[8];
  for (int k = 0; k < 8; ++k) talus[k] = float(std::tan(c.talus_degrees * M_PI / 180.0) * g.distance(k));
  // share[i]: what cell i sends per unit of excess drop (0: nothing).
  std::vector<float> share(n), next(n);
  for (int32_t it = 0; it < c.iterations; ++it) {
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        float total = 0.0f, largest = 0.0f;
        for (int k = 0; k < 8; ++k) {
          const int64_t j = g.neighbour(x, y, k);
          if (j < 0) continue;
          const float excess = z[i] - z[j] - talus[k];
          if (excess > 0.0f) {
            total += excess;
            largest = std::max(largest, excess);
          }
        }
        share[i] = total > 0.0f ? float(c.rate) * 0.5f * largest / total : 0.0f;
      }
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        float sent = 0.0f, received = 0.0f;
        for (int k = 0; k < 8; ++k) {
          const int64_t j = g.neighbour(x, y, k);
          if (j < 0) continue;
          const float down = z[i] - z[j] - talus[k];
          if (down > 0.0f) sent += share[i] * down;
          const float up = z[j] - z[i] - talus[(k + 4) & 7];
          if (up > 0.0f) received += share[j] * up;
        }
        next[i] = z[i] - sent + received;
      }
    std::copy(next.begin(), next.end(), z);
    progress.report(double(it + 1) / c.iterations);
  }
}

}  // namespace ft::erosion
