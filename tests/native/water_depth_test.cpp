// SPDX-License-Identifier: GPL-3.0-or-later
// The water depth rule (native/src/hydrology): no lake surface lies flush
// with the ground (a lake is where its level covers the ground by more than
// the minimum depth, 1% of the relief by default, and its shoreline runs where
// the water is that deep), rivers on a flat plain start no parallel streaks,
// and the ground under every river is carved so its vertices lie on or in
// their bed, never below the sea. On the add-on's default mountain (seed 13,
// the one the issue measured: 40% of its lake cells held less than 1% of the
// relief of water, its lake rims lay on the plain at z = 0) and three more
// seeds, as `fracterra rivers` traces them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hydrology/hydrology.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "terrain/terrain.hpp"
#include "test_terrains.hpp"

namespace ft::hydrology {
namespace {

constexpr uint64_t kSeeds[] = {13, 1, 2, 3};

double relief(const Heightfield& hf) {
  const HeightStats s = hf.stats();
  return double(s.max) - double(s.min);
}

// The ground at world point (x, y), bilinear between samples (the shorelines'
// marching squares interpolate linearly along the grid's edges, where their
// vertices lie, so there it is exact).
double ground_at(const Heightfield& hf, double spacing, double x, double y) {
  const double gx = std::clamp(x / spacing, 0.0, double(hf.width() - 1));
  const double gy = std::clamp(y / spacing, 0.0, double(hf.height() - 1));
  const int32_t x0 = std::min(int32_t(gx), hf.width() - 2), y0 = std::min(int32_t(gy), hf.height() - 2);
  const double fx = gx - x0, fy = gy - y0;
  return (1 - fy) * ((1 - fx) * hf.at(x0, y0) + fx * hf.at(x0 + 1, y0)) +
         fy * ((1 - fx) * hf.at(x0, y0 + 1) + fx * hf.at(x0 + 1, y0 + 1));
}

// Even-odd: is (x, y) inside the lake's rings?
bool inside(const PolylineSet& rings, const Lake& lake, double x, double y) {
  bool in = false;
  for (int64_t r = lake.first_ring; r < lake.first_ring + lake.ring_count; ++r) {
    const int64_t b = rings.line_begin(r), e = rings.line_end(r);
    for (int64_t i = b, j = e - 1; i < e; j = i++) {
      const Vec3 &p = rings.points[size_t(i)], &q = rings.points[size_t(j)];
      if ((p[1] > y) != (q[1] > y) && x < (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]) + p[0]) in = !in;
    }
  }
  return in;
}

TEST(WaterDepth, NoLakeLiesWithinTheMinimumDepthOfTheGround) {
  for (const uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Heightfield hf = test::default_mountain(8, seed);
    const RiverNetwork net = extract_rivers(hf, HydrologyConfig{});
    const double md = net.water.min_depth, sp = net.grid.spacing;
    EXPECT_NEAR(md, 0.01 * relief(hf), 1e-9) << "0: 1% of the relief";
    ASSERT_GT(net.water.lakes.size(), 3u) << "the test needs lakes";
    // Every lake is deeper than md somewhere (seed 1, the CLI's command in
    // the issue, had 43 lakes, now 37: the rest were shallower than md).
    std::vector<double> deepest(net.water.lakes.size(), 0.0);
    for (size_t i = 0; i < hf.size(); ++i)
      if (net.water.label[i] >= 0)
        deepest[size_t(net.water.label[i])] = std::max(deepest[size_t(net.water.label[i])],
                                                       net.water.lakes[size_t(net.water.label[i])].level - hf.data()[i]);
    for (const double d : deepest) EXPECT_GT(d, md);
    for (const Lake& lake : net.water.lakes) {
      ASSERT_GT(lake.ring_count, 0);
      // The shoreline: where the ground lies md under the level (exact up to
      // float heights: 1e-5 of the relief).
      for (int64_t r = lake.first_ring; r < lake.first_ring + lake.ring_count; ++r)
        for (int64_t v = net.lake_rings.line_begin(r); v < net.lake_rings.line_end(r); ++v) {
          const Vec3& p = net.lake_rings.points[size_t(v)];
          ASSERT_EQ(p[2], lake.level);
          ASSERT_NEAR(lake.level - ground_at(hf, sp, p[0], p[1]), md, 1e-5 * relief(hf));
        }
    }
    // Every sample inside a lake's rings is under it by more than md, and
    // every lake cell that deep is inside: the polygon is the deep water.
    int32_t in_rings = 0;
    for (int32_t y = 0; y < hf.height(); ++y)
      for (int32_t x = 0; x < hf.width(); ++x) {
        const int32_t label = net.water.label[size_t(y) * hf.width() + x];
        for (size_t l = 0; l < net.water.lakes.size(); ++l) {
          const Lake& lake = net.water.lakes[l];
          const bool in = inside(net.lake_rings, lake, x * sp, y * sp);
          in_rings += in;
          if (in) EXPECT_GT(lake.level - hf.at(x, y), md) << x << ", " << y;
          if (label == int32_t(l) && lake.level - hf.at(x, y) > md) EXPECT_TRUE(in) << x << ", " << y;
        }
      }
    EXPECT_GT(in_rings, 10);
  }
}

TEST(WaterDepth, AShallowHollowIsNoLakeAndAGivenDepthCounts) {
  // A bowl 0.5 deep in a plain 100 high: 1% of the relief (1.0) is deeper than
  // the bowl, so it is no lake; with min_depth 0.1 given, it is one.
  const Heightfield hf = [] {
    Heightfield h(41, 41);
    for (int32_t y = 0; y < 41; ++y)
      for (int32_t x = 0; x < 41; ++x) {
        const double r = std::hypot(x - 20.0, y - 20.0);
        h.at(x, y) = float(r < 8 ? 0.5 * (r / 8) * (r / 8) : 0.5);
      }
    h.at(40, 40) = 100.0f;  // the relief, far from the bowl
    h.at(0, 20) = 0.25f;    // the plain drains to the edge
    h.set_world_size(40.0);
    return h;
  }();
  HydrologyConfig c;
  c.min_area = 4;
  c.min_lake_area = 0;
  EXPECT_TRUE(extract_rivers(hf, c).water.lakes.empty());
  c.min_depth = 0.1;
  const RiverNetwork net = extract_rivers(hf, c);
  ASSERT_EQ(net.water.lakes.size(), 1u);
  EXPECT_EQ(net.water.min_depth, 0.1);
  // Its cells: all the level floods (r < 8); its shoreline encloses those
  // under it by more than 0.1 (r < 8 sqrt(0.8)).
  int32_t cells = 0, deep = 0, in = 0;
  for (int32_t y = 0; y < 41; ++y)
    for (int32_t x = 0; x < 41; ++x) {
      const double r = std::hypot(x - 20.0, y - 20.0);
      cells += r < 8, deep += r < 8 * std::sqrt(0.8);
      in += inside(net.lake_rings, net.water.lakes[0], x, y);
    }
  EXPECT_EQ(net.water.lakes[0].cells, cells);
  EXPECT_EQ(in, deep);
}

TEST(WaterDepth, NoRiverStartsOnAFlatPlain) {
  // Before: 43 of seed 1's 219 channel heads lay on the plain the falloff
  // levels to z = 0, each the head of a straight streak to the map's edge.
  // A head may still lie on the plain where water from the slopes (each
  // inflow under min_area) gathers on its way across to the nearest river
  // (plains.cpp): slope water, not the plain's own cells, which add none.
  // 2-9 of 184-239 heads (1-4.7%) since rivers gather on the plain (0-2%
  // when each ran straight to the edge); at most 6%, far under the 20% the
  // plain's own cells started.
  for (const uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Heightfield hf = test::default_mountain(8, seed);
    const RiverNetwork net = extract_rivers(hf, HydrologyConfig{});
    const double sp = net.grid.spacing;
    std::vector<uint8_t> fed(net.segments.size(), 0);
    for (const Segment& t : net.segments)
      if (t.downstream >= 0) fed[size_t(t.downstream)] = 1;
    int32_t heads = 0, flat = 0;
    for (size_t k = 0; k < net.segments.size(); ++k) {
      const Segment& s = net.segments[k];
      if (fed[k] || s.from_lake >= 0) continue;
      ++heads;
      const Vec3& p = net.lines.points[size_t(s.first_vertex)];
      const int32_t x = int32_t(std::lround(p[0] / sp)), y = int32_t(std::lround(p[1] / sp));
      float lo = INFINITY, hi = -INFINITY;
      for (int32_t dy = -1; dy <= 1; ++dy)
        for (int32_t dx = -1; dx <= 1; ++dx) {
          const int32_t cx = std::clamp(x + dx, 0, hf.width() - 1), cy = std::clamp(y + dy, 0, hf.height() - 1);
          lo = std::min(lo, hf.at(cx, cy)), hi = std::max(hi, hf.at(cx, cy));
        }
      flat += !(hi - lo > 1e-6);
    }
    std::printf("seed %llu: %d of %d heads on a flat\n", (unsigned long long)seed, flat, heads);
    EXPECT_GT(heads, 50);
    EXPECT_LE(flat, 0.06 * heads);
  }
}

// Rivers across the plain gather and wander (hydrology/plains.cpp). Two
// measures of what the eye saw, on the default mountain's plain at z = 0:
//  - of the rivers that come onto the plain (a segment's step from off it
//    onto it), the share that leave it at the map's edge, each in its own
//    channel: 0.40, 0.56, 0.39 and 0.33 on seeds 13, 1, 2, 3 when the plain
//    was graded by Priority-Flood's epsilon steps (one straight streak per
//    gully); 0.14, 0.21, 0.12 and 0.20 now. Bound 0.27, between.
//  - the longest stretch of one river within 3 cells of the map's edge:
//    101-104 cells before (rivers ran along the edge, where the steps are
//    float ulps and ties go east: a thick band in renders); 7-12 now (a river
//    wanders some cells near the edge before it leaves). Bound 25 cells.
TEST(WaterDepth, RiversOnAPlainGatherAndNeverRunAlongTheEdge) {
  for (const uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Heightfield hf = test::default_mountain(8, seed);
    const RiverNetwork net = extract_rivers(hf, HydrologyConfig{});
    const double sp = net.grid.spacing;
    auto on_plain = [&](const Vec3& p) {
      const int32_t x = std::clamp(int32_t(std::lround(p[0] / sp)), 0, hf.width() - 1);
      const int32_t y = std::clamp(int32_t(std::lround(p[1] / sp)), 0, hf.height() - 1);
      return std::fabs(hf.at(x, y)) <= 1e-6f;
    };
    auto from_edge = [&](const Vec3& p) {
      return std::min({p[0] / sp, p[1] / sp, hf.width() - 1 - p[0] / sp, hf.height() - 1 - p[1] / sp});
    };
    int32_t onto = 0, leave = 0;
    double longest = 0;
    for (const Segment& s : net.segments) {
      const Vec3* v = net.lines.points.data() + s.first_vertex;
      double run = 0;
      for (int64_t k = 1; k < s.vertex_count; ++k) {
        onto += on_plain(v[k]) && !on_plain(v[k - 1]);
        if (from_edge(v[k]) < 3 && from_edge(v[k - 1]) < 3)
          run += std::hypot(v[k][0] - v[k - 1][0], v[k][1] - v[k - 1][1]) / sp;
        else
          run = 0;
        longest = std::max(longest, run);
      }
      leave += s.end == RiverEnd::kEdge && s.vertex_count >= 2 && on_plain(v[s.vertex_count - 2]);
    }
    std::printf("seed %llu: %d rivers onto the plain, %d leave it at the edge (%.2f); longest run along the edge %.1f cells\n",
                (unsigned long long)seed, onto, leave, double(leave) / onto, longest);
    ASSERT_GT(onto, 50) << "the test needs rivers crossing the plain";
    EXPECT_LE(leave, 0.27 * onto);
    EXPECT_LE(longest, 25.0);
  }
}

// The vertices of every river on or in its carved bed: the carved ground
// (bilinear) at each vertex at most the river's surface plus a tolerance.
// The bed's trough is the river's depth under it at the centre line; a vertex
// lies at most sqrt(2)/2 spacing from the cell corners that weigh most, all
// of them inside the bed's half width (at least 0.75 spacing), so the
// tolerance is that of the bilinear reading across a corner outside it: 2%
// of the relief, found 0.3-0.9% at most on these seeds.
void expect_rivers_in_their_beds(const RiverNetwork& net, const Heightfield& carved, double tolerance) {
  const double sp = net.grid.spacing;
  int64_t above = 0;
  double worst = 0;
  for (size_t v = 0; v < net.lines.points.size(); ++v) {
    const Vec3& p = net.lines.points[v];
    const double over = ground_at(carved, sp, p[0], p[1]) - p[2];
    worst = std::max(worst, over);
    above += over > tolerance;
  }
  EXPECT_EQ(above, 0) << "worst " << worst << " above the river (tolerance " << tolerance << ")";
}

TEST(WaterDepth, RiversLieInTheirCarvedBedsNeverBelowTheSea) {
  for (const uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Heightfield hf = test::default_mountain(8, seed);
    HydrologyConfig c;
    c.sea = Sea::kFraction;
    c.sea_fraction = 0.3;  // above the plain: a real coast
    const RiverNetwork net = extract_rivers(hf, c);
    const Heightfield carved = carve(hf, net);
    const double sea = net.water.sea_level;
    size_t lowered = 0;
    for (size_t i = 0; i < hf.size(); ++i) {
      ASSERT_LE(carved.data()[i], hf.data()[i]);
      if (net.water.label[i] != kLand) ASSERT_EQ(carved.data()[i], hf.data()[i]) << "sea and lakes keep theirs";
      if (hf.data()[i] >= sea) ASSERT_GE(carved.data()[i], float(sea)) << "a bed below the sea at " << i;
      lowered += carved.data()[i] < hf.data()[i];
    }
    EXPECT_GT(lowered, 1000u);
    expect_rivers_in_their_beds(net, carved, 0.02 * relief(hf));
  }
}

TEST(WaterDepth, ThePipelinesRiversComeWithTheirGroundCarved) {
  ft_terrain_params t = terrain::default_terrain_params();
  t.method = FT_TERRAIN_MIDPOINT;
  t.levels = 7;
  t.width = t.height = 129;
  t.seed = 13;
  t.sigma = 2.0, t.levelling = 1.0, t.height_offset = 1.5;
  t.falloff = FT_FALLOFF_RADIAL, t.falloff_width = 0.9;
  t.world_size = 10.0;
  t.sea = FT_SEA_HEIGHT;
  t.sea_level = 0.3;
  ft_build_params b = defaults_of<ft_build_params>(pipeline::build_param_table());
  b.terrain = &t;
  const Heightfield plain = pipeline::build_terrain(b, nullptr);
  RiverNetwork net;
  const Heightfield carved = pipeline::build_terrain(b, nullptr, &net);
  size_t lowered = 0;
  for (size_t i = 0; i < plain.size(); ++i) {
    ASSERT_LE(carved.data()[i], plain.data()[i]);
    if (net.water.label[i] == kSea) ASSERT_EQ(carved.data()[i], plain.data()[i]) << "sea cells are never lowered";
    if (plain.data()[i] >= 0.3f) ASSERT_GE(carved.data()[i], 0.3f) << "no bed below the sea";
    lowered += carved.data()[i] < plain.data()[i];
  }
  EXPECT_GT(lowered, 200u);
  expect_rivers_in_their_beds(net, carved, 0.02 * relief(plain));
}

}  // namespace
}  // namespace ft::hydrology
