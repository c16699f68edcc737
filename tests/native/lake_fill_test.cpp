// SPDX-License-Identifier: GPL-3.0-or-later
// Sediment settling in a lake (erosion/lake_fill.hpp): a flat floor from the
// lowest cell up, holding exactly the load, never above the water surface.
// The references are independent of its sort: the lake is found by a flood
// over neighbouring cells under the same surface, and the floor's level by
// bisection on the volume below it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.hpp"
#include "erosion/basin_graph.hpp"
#include "erosion/lake_fill.hpp"

namespace ft::erosion {
namespace {

// White noise in a bowl: lakes of many sizes, lakes within lakes.
std::vector<float> bowl(int32_t w, int32_t h, uint64_t seed) {
  std::vector<float> z(size_t(w) * h);
  uniform_fill(seed, Counter{0, 0, Stream::kFirstUser}, 0, z.size(), z.data());
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      const double dx = x - w / 2.0, dy = y - h / 2.0;
      z[size_t(y) * w + x] += float(2.0 * (dx * dx + dy * dy) / double(w * w));
    }
  return z;
}

// The cells of the lake around `cell`: 8-neighbours under the same surface.
std::vector<int32_t> lake_around(const D8Grid& g, const std::vector<float>& z, const std::vector<float>& surface,
                                 int32_t cell) {
  std::vector<uint8_t> seen(z.size(), 0);
  std::vector<int32_t> lake, todo = {cell};
  seen[cell] = 1;
  while (!todo.empty()) {
    const int32_t v = todo.back();
    todo.pop_back();
    lake.push_back(v);
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(v % g.width, v / g.width, k);
      if (j >= 0 && !seen[j] && surface[j] > z[j] && surface[j] == surface[cell]) seen[j] = 1, todo.push_back(int32_t(j));
    }
  }
  return lake;
}

// The volume (in cell areas) below `level` over `cells`.
double held(const std::vector<float>& z, const std::vector<int32_t>& cells, double level) {
  double v = 0;
  for (int32_t c : cells) v += std::max(0.0, level - z[c]);
  return v;
}

TEST(LakeFill, LaysAFlatFloorHoldingTheLoad) {
  const double cell = 0.25;  // a cell's area: the load is a volume
  int32_t lakes = 0;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    D8Grid g;
    g.width = 57, g.height = 43;
    const std::vector<float> bed = bowl(g.width, g.height, seed);
    FlowGraph graph;
    BasinGraph basins;
    std::vector<float> surface(bed.size());
    route_over_depressions(g, bed.data(), -1, graph, basins, surface.data());
    for (int32_t exit = 0; exit < int32_t(bed.size()); ++exit) {
      // An exit: under a lake, draining to a cell that is not in it.
      const int32_t r = graph.receiver[exit];
      if (!(surface[exit] > bed[exit]) || (surface[r] > bed[r] && surface[r] == surface[exit])) continue;
      const std::vector<int32_t> lake = lake_around(g, bed, surface, exit);
      const double capacity = held(bed, lake, surface[exit]) * cell;
      for (const double share : {0.0, 1e-3, 0.3, 0.999, 1.0, 2.5}) {
        std::vector<float> z = bed;
        LakeFill fill(graph, surface.data(), bed.data(), z.data(), cell);
        const double load = share * capacity, laid = fill.fill(exit, load);
        // Holds the load, up to the surface: to the floor's float
        // resolution (one unit in the last place, 2^-23 of heights of about
        // 1-2, on each cell).
        const double resolution = double(lake.size()) * std::ldexp(2.0, -23) * cell;
        EXPECT_NEAR(laid, std::min(load, capacity), 1e-6 * capacity + resolution) << "seed " << seed << " exit " << exit;
        // The floor by bisection on the volume below it.
        double lo = *std::min_element(bed.begin(), bed.end()), hi = surface[exit];
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (held(bed, lake, mid) * cell < load ? lo : hi) = mid;
        }
        const double level = std::min<double>(hi, surface[exit]);
        for (size_t i = 0; i < z.size(); ++i) {
          const bool in_lake = std::find(lake.begin(), lake.end(), int32_t(i)) != lake.end();
          if (!in_lake || !(bed[i] < level)) {
            ASSERT_EQ(z[i], bed[i]) << "cell " << i << " is outside the lake or above its floor";
          } else {
            ASSERT_NEAR(z[i], level, 1e-5) << "cell " << i << ": the floor is flat";
            ASSERT_LE(z[i], surface[exit]);
          }
        }
      }
      ++lakes;
    }
  }
  EXPECT_GT(lakes, 20) << "the bowls should hold lakes to fill";
}

}  // namespace
}  // namespace ft::erosion
