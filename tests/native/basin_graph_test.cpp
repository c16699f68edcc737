// SPDX-License-Identifier: GPL-3.0-or-later
// The basin graph's routing over depressions (erosion/basin_graph.hpp):
// water leaves every depression over its lowest way out, and the water
// surface is the one a filling would make. The references here are
// independent of it: a fixed point of the filling's definition, computed by
// relaxation, and walks along the receivers.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/rng.hpp"
#include "erosion/basin_graph.hpp"
#include "erosion/flow_graph.hpp"

namespace ft::erosion {
namespace {

// White noise plus a gentle bowl: pits everywhere, lakes in lakes, and
// (with `terraces`) heights rounded to 1/16 so that flats and equal passes
// are common.
std::vector<float> pitted(int32_t w, int32_t h, uint64_t seed, bool terraces) {
  std::vector<float> z(size_t(w) * h);
  uniform_fill(seed, Counter{0, 0, Stream::kFirstUser}, 0, z.size(), z.data());
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      float& v = z[size_t(y) * w + x];
      const double dx = x - w / 2.0, dy = y - h / 2.0;
      v = float(v + 2.0 * (dx * dx + dy * dy) / double(w * w));
      if (terraces) v = std::round(v * 16) / 16;
    }
  return z;
}

// The filled surface by its definition, independently of any flood order:
// w = z at base levels and every other cell at max(z, the lowest w of its
// neighbours), the greatest such fixed point below +infinity. Relaxed from
// +infinity until nothing changes (Planchon & Darboux 2001's fixed point).
std::vector<float> filled_by_relaxation(const D8Grid& g, const std::vector<float>& z, int32_t sink) {
  std::vector<float> w(z.size(), std::numeric_limits<float>::infinity());
  for (int32_t i = 0; i < int32_t(z.size()); ++i)
    if (g.is_base(i, sink)) w[i] = z[i];
  for (bool changed = true; changed;) {
    changed = false;
    for (int32_t i = 0; i < int32_t(z.size()); ++i) {
      if (g.is_base(i, sink)) continue;
      float lowest = std::numeric_limits<float>::infinity();
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(i % g.width, i / g.width, k);
        if (j >= 0) lowest = std::min(lowest, w[j]);
      }
      const float next = std::max(z[i], lowest);
      if (next < w[i]) w[i] = next, changed = true;
    }
  }
  return w;
}

struct Routed {
  FlowGraph graph;
  std::vector<float> surface;
};

Routed route(const D8Grid& g, const std::vector<float>& z, int32_t sink, bool rho8, int threads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Routed r;
  r.surface.resize(z.size());
  if (rho8) draw_rho8(g, std::max(sink, 0), 7, r.graph);
  BasinGraph basins;
  route_over_depressions(g, z.data(), sink, r.graph, basins, r.surface.data());
  omp_set_num_threads(saved);
  return r;
}

bool neighbours(const D8Grid& g, int32_t a, int32_t b) {
  for (int k = 0; k < 8; ++k)
    if (g.neighbour(a % g.width, a / g.width, k) == b) return true;
  return false;
}

void expect_drains_over_lowest_passes(const D8Grid& g, const std::vector<float>& z, int32_t sink, bool rho8) {
  const Routed r = route(g, z, sink, rho8, 2);
  const std::vector<float> reference = filled_by_relaxation(g, z, sink);
  const int32_t n = int32_t(z.size());
  int32_t lake_cells = 0;
  for (int32_t i = 0; i < n; ++i) {
    // The water surface is the filling's, exactly (both are heights of
    // cells: no arithmetic in between).
    ASSERT_EQ(r.surface[i], reference[i]) << "cell " << i;
    lake_cells += r.surface[i] > z[i];
    const int32_t rec = r.graph.receiver[i];
    ASSERT_EQ(rec == i, g.is_base(i, sink)) << "only base levels are their own receivers: cell " << i;
    if (rec != i) ASSERT_TRUE(neighbours(g, i, rec)) << "cell " << i << " drains to " << rec;
    // Walking the receivers reaches a base level, and the highest cell on
    // the way is the water surface: the water leaves over the lowest pass.
    float highest = z[i];
    int32_t c = i, steps = 0;
    while (r.graph.receiver[c] != c) {
      c = r.graph.receiver[c];
      highest = std::max(highest, z[c]);
      ASSERT_LT(++steps, n) << "a cycle through cell " << i;
    }
    ASSERT_EQ(highest, reference[i]) << "cell " << i << " leaves over a pass higher than its lake";
  }
  EXPECT_GT(lake_cells, n / 10) << "the terrain should have lakes to test";
  // The stack: every cell once, each after its receiver.
  std::vector<int32_t> position(size_t(n), -1);
  ASSERT_EQ(int32_t(r.graph.stack.size()), n);
  for (int32_t k = 0; k < n; ++k) {
    ASSERT_EQ(position[r.graph.stack[k]], -1);
    position[r.graph.stack[k]] = k;
  }
  for (int32_t i = 0; i < n; ++i)
    if (r.graph.receiver[i] != i) ASSERT_LT(position[r.graph.receiver[i]], position[i]);
}

TEST(BasinGraph, DrainsEveryDepressionOverItsLowestPass) {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const std::vector<float> z = pitted(61, 47, seed, false);
    D8Grid g;
    g.width = 61, g.height = 47;
    expect_drains_over_lowest_passes(g, z, -1, false);
    expect_drains_over_lowest_passes(g, z, -1, true);
  }
}

TEST(BasinGraph, DrainsFlatsAndEqualPasses) {
  for (uint64_t seed = 4; seed <= 6; ++seed) {
    const std::vector<float> z = pitted(53, 53, seed, true);
    D8Grid g;
    g.width = 53, g.height = 53;
    expect_drains_over_lowest_passes(g, z, -1, true);
  }
}

TEST(BasinGraph, DrainsATorusToItsSinkAndTheSea) {
  std::vector<float> z = pitted(48, 40, 9, false);
  D8Grid g;
  g.width = 48, g.height = 40, g.periodic = true;
  const int32_t sink = periodic_sink(g, z.data());
  expect_drains_over_lowest_passes(g, z, sink, true);
  // A sea: its cells are base levels wherever they are.
  std::vector<uint8_t> sea(z.size(), 0);
  for (size_t i = 0; i < z.size(); ++i) sea[i] = z[i] < 0.12f;
  g.sea = sea.data();
  expect_drains_over_lowest_passes(g, z, sink, true);
}

// A torus shifted across its edges drains alike, shifted: equal passes are
// ordered by Rho8's numbers and positions relative to the sink, not by
// index (with the pair's first-found cells kept, the shifted torus took
// other passes among equals and a pipeline test's erosion differed by 0.18).
TEST(BasinGraph, AShiftedTorusDrainsAlikeShifted) {
  const int32_t w = 64, h = 48, sx = 23, sy = 17;
  const std::vector<float> z = pitted(w, h, 12, true);
  std::vector<float> shifted(z.size());
  auto moved = [&](int32_t i) { return ((i / w + sy) % h) * w + (i % w + sx) % w; };
  for (int32_t i = 0; i < w * h; ++i) shifted[moved(i)] = z[i];
  D8Grid g;
  g.width = w, g.height = h, g.periodic = true;
  const Routed a = route(g, z, periodic_sink(g, z.data()), true, 2);
  const Routed b = route(g, shifted, periodic_sink(g, shifted.data()), true, 2);
  for (int32_t i = 0; i < w * h; ++i) {
    ASSERT_EQ(moved(a.graph.receiver[i]), b.graph.receiver[moved(i)]) << "cell " << i;
    ASSERT_EQ(a.surface[i], b.surface[moved(i)]) << "cell " << i;
  }
}

TEST(BasinGraph, TheRoutingDoesNotDependOnTheThreadCount) {
  const std::vector<float> z = pitted(257, 129, 11, true);
  D8Grid g;
  g.width = 257, g.height = 129;
  const Routed one = route(g, z, -1, true, 1), two = route(g, z, -1, true, 2), three = route(g, z, -1, true, 3);
  EXPECT_EQ(one.graph.receiver, two.graph.receiver);
  EXPECT_EQ(one.graph.receiver, three.graph.receiver);
  EXPECT_EQ(one.graph.stack, two.graph.stack);
  EXPECT_EQ(one.surface, three.surface);
}

}  // namespace
}  // namespace ft::erosion
