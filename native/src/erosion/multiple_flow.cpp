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
  const double cell = g.spacing * g.spacing;
  auto gives = [&](int32_t x, int32_t y) {
    return g.periodic ? int32_t(size_t(y) * g.width + x) != sink : !g.on_edge(x, y);
  };
  // Weight of the water cell i sends toward neighbour k (0 unless lower).
  auto weight = [&](size_t i, int64_t j, int k) {
    const double drop = double(z[i]) - double(z[j]);
    return drop > 0.0 ? kContour[k & 1] * drop / g.distance(k) : 0.0;
  };
  // Each giver's total weight, and each cell's count of higher givers (the
  // inflows it waits for).
  std::vector<double> total(n, 0.0);
  std::vector<uint8_t> waiting(n, 0);
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < g.height; ++y)
    for (int32_t x = 0; x < g.width; ++x) {
      const size_t i = size_t(y) * g.width + x;
      double sum = 0.0;
      uint8_t higher = 0;
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(x, y, k);
        if (j < 0) continue;
        if (gives(int32_t(j % g.width), int32_t(j / g.width)) && z[j] > z[i]) ++higher;
        sum += weight(i, j, k);
      }
      total[i] = gives(x, y) ? sum : 0.0;
      waiting[i] = higher;
    }
  // Kahn's order: a cell is ready when its last higher giver is done. Its
  // area is pulled from its higher givers in neighbour order, so the sums
  // are the same whatever the order of the queue.
  area.assign(n, 0.0);
  std::vector<int32_t> ready;
  ready.reserve(n);
  for (size_t i = 0; i < n; ++i)
    if (waiting[i] == 0) ready.push_back(int32_t(i));
  for (size_t head = 0; head < ready.size(); ++head) {
    const int32_t i = ready[head];
    const int32_t x = i % g.width, y = i / g.width;
    double a = cell;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(x, y, k);
      if (j < 0 || !(z[j] > z[i]) || total[j] <= 0.0) continue;
      a += area[j] * weight(size_t(j), i, (k + 4) & 7) / total[j];
    }
    area[i] = a;
    if (total[i] <= 0.0) continue;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(x, y, k);
      if (j >= 0 && z[j] < z[i] && --waiting[j] == 0) ready.push_back(int32_t(j));
    }
  }
}

}  // namespace ft::erosion
