// Multiple-flow drainage area (see multiple_flow.hpp).
#include "erosion/multiple_flow.hpp"

namespace ft::erosion {
namespace {

// Quinn et al. (1991): the width of the contour a cell shares with a
// neighbour, in cells: half the side toward a cardinal neighbour, a quarter
// of the diagonal toward a diagonal one.
constexpr double kContour[2] = {0.5, M_SQRT2 / 4.0};

}  // namespace

void multiple_flow_area(const D8Grid& g, const float* z, int32_t sink, std::vector<double>& area) {
  const size_t n = g.size();
  const int32_t w = g.width, h = g.height;
  // Interior cells (all eight neighbours inside, also on a torus) take them
  // at fixed offsets; the others through the general lookup.
  int64_t offset[8];
  double factor[8];  // contour length over distance
  for (int k = 0; k < 8; ++k) {
    offset[k] = int64_t(kDy[k]) * w + kDx[k];
    factor[k] = kContour[k & 1] / g.distance(k);
  }
  auto inner = [&](int32_t x, int32_t y) { return x > 0 && y > 0 && x < w - 1 && y < h - 1; };
  auto nbr = [&](int64_t i, int32_t x, int32_t y, bool in, int k) { return in ? i + offset[k] : g.neighbour(x, y, k); };
  // A base level keeps what reaches it; every other cell gives.
  auto gives = [&](int64_t i, int32_t x, int32_t y) { return g.periodic ? i != sink : inner(x, y); };
  // How many higher givers each cell waits for. Rows in parallel: each cell
  // writes only its own count.
  std::vector<uint8_t> waiting(n, 0);
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      const int64_t i = int64_t(y) * w + x;
      const bool in = inner(x, y);
      uint8_t higher = 0;
      for (int k = 0; k < 8; ++k) {
        const int32_t nx = x + kDx[k], ny = y + kDy[k];
        // A bounded grid's edge cells never give. (A torus's sink does not
        // either, but it is the lowest cell: never a higher one.)
        if (!g.periodic && !inner(nx, ny)) continue;
        higher += z[nbr(i, x, y, in, k)] > z[i];
      }
      waiting[size_t(i)] = higher;
    }
  // Kahn's order: a cell is ready when its last higher giver has passed its
  // water on; then its area is final and it passes it on in turn. The ready
  // cells are a stack, so the cell taken next is usually one just made
  // ready beside the last: its neighbourhood is still in the cache (a
  // first-in first-out queue wanders over the grid and took 1.4 times as
  // long at 1025^2). The stack is serial and starts in index order, so
  // every sum is made in the same order on any thread count.
  area.assign(n, g.spacing * g.spacing);
  std::vector<int32_t> ready;
  ready.reserve(n);
  for (size_t i = n; i-- > 0;)
    if (waiting[i] == 0) ready.push_back(int32_t(i));
  double share[8];
  int64_t lower[8];
  while (!ready.empty()) {
    const int32_t i = ready.back();
    ready.pop_back();
    const int32_t x = i % w, y = i / w;
    if (!gives(i, x, y)) continue;
    const bool in = inner(x, y);
    double total = 0.0;
    int count = 0;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = nbr(i, x, y, in, k);
      if (j < 0 || !(z[j] < z[i])) continue;
      share[count] = factor[k] * (double(z[i]) - double(z[j]));
      total += share[count];
      lower[count++] = j;
    }
    const double give = area[size_t(i)] / total;
    for (int c = 0; c < count; ++c) {
      area[size_t(lower[c])] += give * share[c];
      if (--waiting[size_t(lower[c])] == 0) ready.push_back(int32_t(lower[c]));
    }
  }
}

}  // namespace ft::erosion
