// Slope and curvature maps by central differences on the D8 grid.
#include <cmath>

#include "erosion/erosion.hpp"

namespace ft::erosion {

void slope_curvature(const D8Grid& g, const float* z, float* slope, float* curvature) {
  const double inv = 1.0 / g.spacing;
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < g.height; ++y)
    for (int32_t x = 0; x < g.width; ++x) {
      const size_t i = size_t(y) * g.width + x;
      // A missing neighbour at a bounded edge mirrors the one opposite, so
      // the differences become one-sided and the Laplacian stays second order.
      double nbr[4];
      for (int p = 0; p < 4; ++p) {
        const int64_t j = g.neighbour(x, y, 2 * p);
        const int64_t o = g.neighbour(x, y, (2 * p + 4) & 7);
        nbr[p] = j >= 0 ? z[j] : (o >= 0 ? 2.0 * z[i] - z[o] : z[i]);
      }
      const double gx = 0.5 * (nbr[0] - nbr[2]) * inv, gy = 0.5 * (nbr[1] - nbr[3]) * inv;
      slope[i] = float(std::sqrt(gx * gx + gy * gy));  // no overflow to guard against: hypot costs
      curvature[i] = float((nbr[0] + nbr[1] + nbr[2] + nbr[3] - 4.0 * z[i]) * inv * inv);
    }
}

}  // namespace ft::erosion
