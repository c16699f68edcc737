// SPDX-License-Identifier: GPL-3.0-or-later
// The landscape model (issue 24): every preset at its default strength keeps
// the landform (shape and height) and grows no spike, on the add-on's
// default mountain and on fBm terrains; the same terrain eroded at 257^2 and
// 2049^2 agrees; masks and strength, with bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/flow_graph.hpp"
#include "erosion/multiple_flow.hpp"
#include "erosion/presets.hpp"
#include "terrain/terrain.hpp"
#include "sanitizer.hpp"
#include "test_grids.hpp"
#include "test_terrains.hpp"

namespace ft::erosion {
namespace {

using test::default_mountain;
using test::downsample;

// fBm: the same terrain at every size (issue 24 measured 0.996 at shared
// points), so it is the input of the resolution test. With `sea_fraction`
// an island: the landform's sea covers that share, flat at the lowest height
// (terrain/landform.cpp).
Heightfield make_fbm(int32_t size, uint64_t seed, double sea_fraction = 0) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = FT_TERRAIN_FBM;
  p.width = p.height = size;
  p.seed = seed;
  p.hurst = 0.8;
  p.world_size = 10.0;
  if (sea_fraction > 0) p.sea = FT_SEA_FRACTION, p.sea_fraction = sea_fraction;
  Heightfield hf = terrain::generate_terrain(p);
  hf.set_world_size(10.0);
  return hf;
}

// fBm terrains are made once per test program (a 2049^2 one takes a good
// part of a second, and several tests erode the same seeds).
const Heightfield& fbm(int32_t size, uint64_t seed) {
  static std::map<std::pair<int32_t, uint64_t>, Heightfield> made;
  auto it = made.find({size, seed});
  if (it == made.end()) it = made.emplace(std::pair{size, seed}, make_fbm(size, seed)).first;
  return it->second;
}

std::vector<float> values(const Heightfield& hf) { return {hf.data(), hf.data() + hf.size()}; }

// A box filter `r` samples each side along x then y, `passes` times (twice:
// close to a Gaussian), clamped at the edges.
std::vector<float> smooth(std::vector<float> v, int32_t w, int32_t h, int32_t r, int passes = 2) {
  std::vector<float> t(v.size());
  for (int pass = 0; pass < passes; ++pass) {
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        double s = 0;
        for (int32_t d = -r; d <= r; ++d) s += v[size_t(y) * w + std::clamp(x + d, 0, w - 1)];
        t[size_t(y) * w + x] = float(s / (2 * r + 1));
      }
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        double s = 0;
        for (int32_t d = -r; d <= r; ++d) s += t[size_t(std::clamp(y + d, 0, h - 1)) * w + x];
        v[size_t(y) * w + x] = float(s / (2 * r + 1));
      }
  }
  return v;
}

double mean(const std::vector<float>& a) {
  double s = 0;
  for (float v : a) s += v;
  return s / double(a.size());
}

double correlation(const std::vector<float>& a, const std::vector<float>& b) {
  const double ma = mean(a), mb = mean(b);
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

// Least-squares slope of b on a.
double slope(const std::vector<float>& a, const std::vector<float>& b) {
  const double ma = mean(a), mb = mean(b);
  double ab = 0, aa = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
  }
  return ab / aa;
}

// The 99.9th percentile of |5-point Laplacian| over the interior.
double laplacian_p999(const std::vector<float>& z, int32_t w, int32_t h) {
  std::vector<float> l;
  for (int32_t y = 1; y < h - 1; ++y)
    for (int32_t x = 1; x < w - 1; ++x) {
      const size_t i = size_t(y) * w + x;
      l.push_back(std::fabs(z[i - 1] + z[i + 1] + z[i - w] + z[i + w] - 4 * z[i]));
    }
  const size_t k = size_t(0.999 * double(l.size() - 1));
  std::nth_element(l.begin(), l.begin() + k, l.end());
  return l[k];
}

// Straight walls: cells standing more than 1 cm (the default mountain is 10
// units across and about 2 high) above both neighbours across a grid line,
// in runs of 3 or more along it, among the cells `pick` takes. A fractal's
// rough texture rarely lines up so; sediment laid along a lake's carved
// flow path did (issue 24's filled hollow).
size_t straight_walls(const std::vector<float>& z, int32_t w, const std::vector<uint8_t>& pick) {
  constexpr float kTall = 0.01f;
  constexpr int32_t kRun = 3;
  const int32_t h = int32_t(z.size() / size_t(w));
  std::vector<uint8_t> wall(z.size(), 0);
  // across = the step to the neighbours a wall stands above; along = the
  // step along the wall.
  auto scan = [&](int32_t across, int32_t along, int32_t lines, int32_t length, int32_t line_step) {
    for (int32_t line = 1; line < lines - 1; ++line) {
      int32_t run = 0;
      for (int32_t t = 0; t <= length; ++t) {
        const size_t i = size_t(line) * line_step + size_t(t) * along;
        const bool tall = t < length && z[i] - z[i - across] > kTall && z[i] - z[i + across] > kTall;
        if (tall) {
          ++run;
        } else {
          if (run >= kRun)
            for (int32_t b = 1; b <= run; ++b) wall[i - size_t(b) * along] = 1;
          run = 0;
        }
      }
    }
  };
  scan(w, 1, h, w, w);  // walls along x: above the rows before and after
  scan(1, w, w, h, 1);  // walls along y: above the columns either side
  size_t count = 0;
  for (size_t i = 0; i < z.size(); ++i) count += wall[i] && pick[i];
  return count;
}

struct Landform {
  double correlation, slope, max_in, max_out, laplacian_growth;
  // Straight walls where sediment settled (the output above the input by
  // 1 mm), on the model's grid (both terrains averaged over its cells): in
  // the output and in the input at the same cells.
  size_t walls_in, walls_out;
};

Landform landform(const Heightfield& in, const Heightfield& out) {
  const int32_t w = in.width(), h = in.height(), r = std::max(1, w / 32);  // 2r + 1 ~ 1/16 of the width
  const std::vector<float> a = smooth(values(in), w, h, r), b = smooth(values(out), w, h, r);
  const int32_t f = std::max(1, (w - 1) / kModelCells);
  const std::vector<float> ma = downsample(values(in), w, f), mb = downsample(values(out), w, f);
  std::vector<uint8_t> deposit(ma.size());
  for (size_t i = 0; i < ma.size(); ++i) deposit[i] = mb[i] > ma[i] + 1e-3f;
  const int32_t mw = (w - 1) / f + 1;
  return {correlation(a, b), slope(a, b), in.stats().max, out.stats().max,
          laplacian_p999(values(out), w, h) / laplacian_p999(values(in), w, h),
          straight_walls(ma, mw, deposit), straight_walls(mb, mw, deposit)};
}

ErosionConfig preset_for(const std::string& id) {
  ErosionConfig c = erosion_preset(id);
  c.threads = 2;
  return c;
}

// Issue 24 part 1 on one terrain. The bounds are the issue's: they are what
// an artist sees as "the same mountain, worn", not statistics of a sample,
// so they hold for every preset and seed, not on average.
void expect_landform_survives(const Heightfield& in, const std::string& id, const std::string& what) {
  const Heightfield out = erode(in, preset_for(id), nullptr);
  const Landform f = landform(in, out);
  std::printf("%-16s %-22s corr %.4f slope %.3f max %.3f -> %.3f laplacian x%.2f walls %zu -> %zu\n", id.c_str(),
              what.c_str(), f.correlation, f.slope, f.max_in, f.max_out, f.laplacian_growth, f.walls_in, f.walls_out);
  EXPECT_GE(f.correlation, 0.95) << id << " " << what;
  EXPECT_GE(f.slope, 0.8) << id << " " << what;
  EXPECT_LE(f.slope, 1.05) << id << " " << what;
  EXPECT_LE(f.max_out, f.max_in) << id << " " << what;
  EXPECT_LE(f.laplacian_growth, 1.5) << id << " " << what;
  EXPECT_LE(f.walls_out, f.walls_in) << id << " " << what << ": straight walls in the deposits";
}

// Each preset is its own test (its own ctest entry: ctest -j spreads the
// ensembles over the cores): ErosionModel/EveryPreset.NAME/PRESET.
class EveryPreset : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(ErosionModel, EveryPreset, ::testing::ValuesIn(erosion_preset_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(EveryPreset, KeepsTheDefaultMountainWithoutSpikes) {
#ifdef FT_UNDER_ASAN
  // Ensembles of large erosions take minutes under ASan; the smaller
  // ErosionModel and Erosion tests run the same code paths under it.
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    expect_landform_survives(default_mountain(8, seed), GetParam(), "levels 8 seed " + std::to_string(seed));
    expect_landform_survives(default_mountain(9, seed), GetParam(), "levels 9 seed " + std::to_string(seed));
  }
  // Levels 10 (where the old Valleys grew its spire) on two seeds: 1025^2
  // runs cost a second each.
  for (uint64_t seed : {1, 5}) expect_landform_survives(default_mountain(10, seed), GetParam(), "levels 10");
}

TEST_P(EveryPreset, KeepsFbmTerrainsWithoutSpikes) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  for (uint64_t seed = 1; seed <= 3; ++seed)
    expect_landform_survives(fbm(257, seed), GetParam(), "fbm 257 seed " + std::to_string(seed));
}

// Issue 24, the demo's eroded relief: a sea at the lowest height took the
// rivers' sediment as deposit and rose into sand flats and specks (370
// sea cells of 513^2 above the level in examples/demo.sh). With the sea as
// the base level its floor stays exactly as it was: every cell of it, so no
// speck; no land is cut below it; and the land keeps its landform as on
// terrains without a sea.
// (257^2 runs the model on the terrain's own grid, 513^2 coarse to fine.)
TEST_P(EveryPreset, LeavesTheSeaFloorAsItWas) {
#ifdef FT_UNDER_ASAN
  const std::vector<int32_t> sizes = {257};  // 513^2 runs take long under ASan; the code paths are the same
#else
  const std::vector<int32_t> sizes = {257, 513};
#endif
  for (int32_t size : sizes)
    for (uint64_t seed = 1; seed <= 2; ++seed) {
      const Heightfield in = make_fbm(size, seed, 0.3);
      const float level = in.stats().min;
      ErosionConfig c = preset_for(GetParam());
      c.sea = Sea::kHeight;
      c.sea_level = level;
      const Heightfield out = erode(in, c, nullptr);
      std::vector<uint8_t> sea(in.size());
      size_t sea_count = 0, changed = 0, below = 0;
      for (size_t i = 0; i < in.size(); ++i) {
        sea[i] = in.data()[i] <= level;
        if (sea[i]) ++sea_count, changed += out.data()[i] != in.data()[i];
        else below += out.data()[i] < level;
      }
      EXPECT_GT(sea_count, in.size() / 5) << size << " seed " << seed;  // the island has its sea
      EXPECT_EQ(changed, 0u) << GetParam() << " " << size << " seed " << seed << ": sea cells changed";
      EXPECT_EQ(below, 0u) << GetParam() << " " << size << " seed " << seed << ": land cut below the sea";
      const Landform f = landform(in, out);
      EXPECT_GE(f.correlation, 0.95) << GetParam() << " " << size << " seed " << seed;
      EXPECT_LE(f.max_out, f.max_in) << GetParam() << " " << size << " seed " << seed;
      // Without the sea the same run lays sediment on its floor (what the
      // test guards against: it can fail).
      if (size == 257 && seed == 1) {
        c.sea = Sea::kNone;
        const Heightfield open = erode(in, c, nullptr);
        size_t raised = 0;
        for (size_t i = 0; i < in.size(); ++i) raised += sea[i] && open.data()[i] > in.data()[i];
        EXPECT_GT(raised, 0u) << GetParam() << ": without a sea, sediment settles on its floor";
      }
    }
}

TEST(ErosionModel, WhatReachesTheSeaIsCarriedAway) {
  // No creep: the volume is exactly bookkept, and the sea takes what the
  // bed lost and no deposit kept. (At 257^2: the budget is of the model's
  // grid, which is this terrain's own only at that size.)
  const Heightfield in = make_fbm(257, 3, 0.3);
  ErosionConfig c = preset_for("alluvial_fans");
  c.fluvial.diffusion = 0;
  c.model.strength = 1;
  MassBudget open_budget, sea_budget;
  erode(in, c, nullptr, &open_budget);
  c.sea = Sea::kFraction;  // the landform's convention: its sea is this quantile
  c.sea_fraction = 0.3;
  const Heightfield out = erode(in, c, nullptr, &sea_budget);
  double change = 0;
  for (size_t i = 0; i < in.size(); ++i) change += out.data()[i] - in.data()[i];
  const double cell = std::pow(grid_of(in, false).spacing, 2);
  // (The one-cell pits lifted are from no bed: filled_pits.)
  EXPECT_NEAR(change * cell, sea_budget.deposited - sea_budget.detached + sea_budget.filled_pits,
              1e-5 * sea_budget.detached + 1e-6);
  EXPECT_NEAR(sea_budget.detached, sea_budget.deposited + sea_budget.carried_out, 1e-9 * sea_budget.detached);
  // The coast is nearer than the map's edge: more leaves.
  EXPECT_GT(sea_budget.carried_out, open_budget.carried_out);
}

TEST(ErosionModel, SedimentWhereTheFalloffEndsIsAsSmoothAsTheRest) {
#ifdef FT_UNDER_ASAN
  // Ensembles of large erosions take minutes under ASan; the smaller
  // ErosionModel and Erosion tests run the same code paths under it.
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // The ring the old Rain left: where the radial falloff meets the flat
  // edge (radius 0.9 of the half width), the eroded terrain's |Laplacian|
  // at its 99th percentile is no more than 1.5 times that over the whole
  // map's land, for every preset.
  for (const auto& preset : erosion_presets())
    for (uint64_t seed : {1, 3}) {
      const Heightfield in = default_mountain(9, seed), out = erode(in, preset_for(preset.id), nullptr);
      const int32_t w = out.width();
      std::vector<float> ring, all;
      for (int32_t y = 1; y < w - 1; ++y)
        for (int32_t x = 1; x < w - 1; ++x) {
          const size_t i = size_t(y) * w + x;
          const float* z = out.data();
          const float l = std::fabs(z[i - 1] + z[i + 1] + z[i - w] + z[i + w] - 4 * z[i]);
          const double u = 2.0 * x / (w - 1) - 1, v = 2.0 * y / (w - 1) - 1, rad = std::sqrt(u * u + v * v);
          if (rad < 0.95) all.push_back(l);
          if (rad > 0.8 && rad < 0.95) ring.push_back(l);
        }
      auto p99 = [](std::vector<float> s) {
        const size_t k = size_t(0.99 * double(s.size() - 1));
        std::nth_element(s.begin(), s.begin() + k, s.end());
        return double(s[k]);
      };
      EXPECT_LE(p99(ring), 1.5 * p99(all)) << preset.id << " seed " << seed;
    }
}

// --- The same terrain at every resolution -----------------------------

// Cells whose multiple-flow area is above 1% of the map's.
std::vector<uint8_t> channels(const Heightfield& hf) {
  const D8Grid g = grid_of(hf, false);
  std::vector<float> z = values(hf);
  FlowGraph graph;
  route_and_fill(g, z.data(), -1, graph);
  std::vector<double> area;
  multiple_flow_area(g, z.data(), -1, area);
  const double map = double(hf.width() - 1) * (hf.height() - 1) * g.spacing * g.spacing;
  std::vector<uint8_t> c(area.size());
  for (size_t i = 0; i < area.size(); ++i) c[i] = area[i] > 0.01 * map;
  return c;
}

// The share of `a`'s channel cells with a channel of `b` within one cell (a
// channel's position on a grid is known to one cell).
double shared(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int32_t w) {
  int64_t in_a = 0, matched = 0;
  for (int32_t y = 0; y < w; ++y)
    for (int32_t x = 0; x < w; ++x) {
      if (!a[size_t(y) * w + x]) continue;
      ++in_a;
      bool near = false;
      for (int32_t dy = -1; dy <= 1 && !near; ++dy)
        for (int32_t dx = -1; dx <= 1 && !near; ++dx) {
          const int32_t nx = x + dx, ny = y + dy;
          near = nx >= 0 && ny >= 0 && nx < w && ny < w && b[size_t(ny) * w + nx];
        }
      matched += near;
    }
  return in_a ? double(matched) / double(in_a) : 1.0;
}

// The energy of the terrain less its smoothing over 3 x 3 cells (twice):
// the finest texture a grid shows.
double texture_energy(const std::vector<float>& z, int32_t w) {
  const int32_t h = int32_t(z.size() / size_t(w));
  const std::vector<float> s = smooth(z, w, h, 1);
  double e = 0;
  for (size_t i = 0; i < z.size(); ++i) e += double(z[i] - s[i]) * (z[i] - s[i]);
  return e;
}

TEST_P(EveryPreset, ErodesTheSameTerrainAlikeAt257And2049) {
#ifdef FT_UNDER_ASAN
  // Ensembles of large erosions take minutes under ASan; the smaller
  // ErosionModel and Erosion tests run the same code paths under it.
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // Issue 24 part 2's bounds, for each preset on three seeds. The inputs
  // themselves differ (fBm at 2049^2 averaged to 257^2 against fBm made at
  // 257^2: correlation ~0.996, relief ~1-2%), so the bounds leave that
  // margin: heights 0.98, erosion depth 0.85, relief 10%, channels 70%.
  // Every metric compares the 257^2 result with the 2049^2 result averaged
  // over each 257^2 cell's footprint; the channels of both are routed on
  // those 257^2 grids, and a channel cell counts as shared when the other
  // has a channel within one cell (both ways).
  // Channels: issue 24 asks 70% per seed, and every preset and seed holds
  // it since the model drains its lakes over the basin graph: 0.77-0.97
  // (when it routed over Priority-Flood fills, Badlands' seed 3 shared
  // 0.64, and the bound was 0.70 on each preset's mean only). Seed 3's
  // inputs themselves share 0.87 / 0.89 of their channels.
  const std::string id = GetParam();
  {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
      const std::string what = id + " seed " + std::to_string(seed);
      const Heightfield &small_in = fbm(257, seed), &big_in = fbm(2049, seed);
      const Heightfield small = erode(small_in, preset_for(id), nullptr);
      const Heightfield big = erode(big_in, preset_for(id), nullptr);
      const std::vector<float> big_down = downsample(values(big), 2049, 8);
      const std::vector<float> big_in_down = downsample(values(big_in), 2049, 8);
      EXPECT_GE(correlation(values(small), big_down), 0.98) << what;
      std::vector<float> depth_small(small.size()), depth_big(small.size());
      for (size_t i = 0; i < small.size(); ++i) {
        depth_small[i] = small.data()[i] - small_in.data()[i];
        depth_big[i] = big_down[i] - big_in_down[i];
      }
      EXPECT_GE(correlation(depth_small, depth_big), 0.85) << what;
      const auto [lo, hi] = std::minmax_element(big_down.begin(), big_down.end());
      const double relief_small = small.stats().max - small.stats().min, relief_big = *hi - *lo;
      EXPECT_NEAR(relief_big / relief_small, 1.0, 0.10) << what;
      // Channels on both at 257^2: the big result downsampled, routed there.
      Heightfield big_at_small(small.width(), small.height());
      std::copy(big_down.begin(), big_down.end(), big_at_small.data());
      big_at_small.set_world_size(small.world_size());
      const std::vector<uint8_t> c_small = channels(small), c_big = channels(big_at_small);
      const double heights = correlation(values(small), big_down), depth = correlation(depth_small, depth_big);
      std::printf("%-22s heights %.4f depth %.4f relief %.4f channels %.3f / %.3f\n", what.c_str(), heights, depth,
                  relief_big / relief_small, shared(c_small, c_big, 257), shared(c_big, c_small, 257));
      const double both = std::min(shared(c_small, c_big, 257), shared(c_big, c_small, 257));
      EXPECT_GE(both, 0.70) << what;
      // The preview looks like the final: at the preview's grid, the
      // final's texture (averaged over the preview's cells), less what leaks
      // through that average of the texture the final keeps by design (its
      // input less the mean over the model's cell, 9 x 9 samples; a preview
      // cannot show it), against the preview's. Both are measured as a share
      // of the input's texture at the preview's grid: erosion wears that to
      // 4-19 % in the preview. The final keeps 1-5 % of the input's more
      // than the preview (its detail run reads a bounded reach and does not
      // route over the texture's depressions, so it wears the texture at
      // the model's cell, which the model's change resampled bilinearly only
      // partly reaches, less than the preview's run on that grid): as a
      // ratio of the preview's worn energy that is 1.3-1.7x, while the
      // difference is 1-5 % of what the terrain had (Scree Slopes 0.8 %,
      // Badlands 4.5 %). A final that
      // kept its input's texture would show about 90 % more, one that wore
      // more than the preview a negative share. Bound: within 10 % of the
      // input's energy either way, twice the largest measured.
      const std::vector<float> kept_texture = [&] {
        std::vector<float> t = values(big_in);
        const std::vector<float> cell_mean = smooth(t, 2049, 2049, 4, 1);
        for (size_t i = 0; i < t.size(); ++i) t[i] -= cell_mean[i];
        return downsample(t, 2049, 8);
      }();
      const double leak = texture_energy(kept_texture, 257);
      const double texture_small = texture_energy(values(small), 257), texture_big = texture_energy(big_down, 257);
      const double texture_in = texture_energy(big_in_down, 257);
      const double excess = (texture_big - leak - texture_small) / texture_in;
      std::printf("%-22s texture energy at 257^2: in %.4g / %.4g, out %.4g / %.4g, leak %.4g, final's excess %.3f\n",
                  what.c_str(), texture_energy(values(small_in), 257), texture_in, texture_small, texture_big, leak,
                  excess);
      EXPECT_NEAR(excess, 0.0, 0.10) << what << ": the final's texture at the preview's grid against the preview's";
    }
  }
}

// The eroded terrain at `levels` against the eroded final (levels 10) at
// the preview's vertices: their mean heights' ratio, and the largest
// difference as a share of the final's relief.
struct AtSharedVertices {
  double mean_ratio, largest;
};
AtSharedVertices against_final(const Heightfield& preview, const Heightfield& final_hf) {
  const int32_t w = preview.width(), stride = (final_hf.width() - 1) / (w - 1);
  double sum_p = 0, sum_f = 0, largest = 0;
  for (int32_t y = 0; y < w; ++y)
    for (int32_t x = 0; x < w; ++x) {
      const float p = preview.at(x, y), f = final_hf.at(x * stride, y * stride);
      sum_p += p, sum_f += f;
      largest = std::max(largest, double(std::fabs(p - f)));
    }
  const HeightStats s = final_hf.stats();
  return {sum_p / sum_f, largest / (s.max - s.min)};
}

TEST_P(EveryPreset, ErodesAPreviewAt65AsItsFinalAt1025) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // Issue 36: Preview Levels 6 (65^2) against Detail Levels 10, Rugged
  // Mountains, seed 13: the preview's mean was 14 % below the final's at
  // their shared vertices (0.323 against 0.375 m). The model ran on the
  // 65^2 grid itself, whose one-cell channels cover 4x the land they do on
  // the model's grid. Now a terrain narrower than the model's grid is
  // resampled onto it: every preset and seed here is within 0.7 % (bound:
  // the 3 %). The largest difference at shared vertices is where a
  // channel of one lies a model cell from the other's (the preview cannot
  // see the detail that places it): 3-17 % of the relief, as a 257^2
  // preview has against the same final (3-14 %; the preview at 65^2 is up
  // to 1.25x that). Held to 1.5x the 257^2 preview's. (Broken on purpose,
  // the 65^2 run on its own grid again: Rugged Mountains mean x0.84-0.86 on
  // these seeds, largest 0.23 of the relief against 0.14 at 257^2 on seed
  // 13, 45 cm; Scree Slopes x0.96.)
  for (uint64_t seed : {1, 2, 13}) {
    const ErosionConfig c = preset_for(GetParam());
    const Heightfield final_hf = erode(default_mountain(10, seed), c, nullptr);
    const AtSharedVertices at65 = against_final(erode(default_mountain(6, seed), c, nullptr), final_hf);
    const AtSharedVertices at257 = against_final(erode(default_mountain(8, seed), c, nullptr), final_hf);
    std::printf("%-16s seed %2d: 65^2 against 1025^2: mean x%.4f, largest %.3f of the relief (257^2: x%.4f, %.3f)\n",
                GetParam().c_str(), int(seed), at65.mean_ratio, at65.largest, at257.mean_ratio, at257.largest);
    EXPECT_NEAR(at65.mean_ratio, 1.0, 0.03) << GetParam() << " seed " << seed;
    EXPECT_LE(at65.largest, 1.5 * at257.largest) << GetParam() << " seed " << seed;
  }
}

// --- What the demo's reliefs showed ------------------------------------

// The p-th quantile of |5-point Laplacian| over the cells (x, y), 1 <= x <
// w - 1 and 1 <= y < h - 1, that `pick(x, y)` takes.
template <class Pick>
double laplacian_quantile(const float* z, int32_t w, int32_t h, double p, Pick pick) {
  std::vector<float> l;
  for (int32_t y = 1; y < h - 1; ++y)
    for (int32_t x = 1; x < w - 1; ++x) {
      if (!pick(x, y)) continue;
      const size_t i = size_t(y) * w + x;
      l.push_back(std::fabs(z[i - 1] + z[i + 1] + z[i - w] + z[i + w] - 4 * z[i]));
    }
  const size_t k = size_t(p * double(l.size() - 1));
  std::nth_element(l.begin(), l.begin() + k, l.end());
  return l[k];
}

// The roughest of the four borders (the 4 rows or columns next to the edge)
// against the interior (16 cells and more from the edge): p99 of
// |Laplacian|, as a ratio.
double border_roughness(const Heightfield& hf) {
  const int32_t w = hf.width(), h = hf.height(), band = 4, inner = 16;
  const float* z = hf.data();
  const double interior = laplacian_quantile(z, w, h, 0.99, [&](int32_t x, int32_t y) {
    return std::min({x, y, w - 1 - x, h - 1 - y}) >= inner;
  });
  double worst = 0;
  for (int side = 0; side < 4; ++side) {
    const double border = laplacian_quantile(z, w, h, 0.99, [&](int32_t x, int32_t y) {
      const int32_t d[4] = {y, h - 1 - y, x, w - 1 - x};
      return d[side] <= band && std::min({x, y, w - 1 - x, h - 1 - y}) >= 1;
    });
    worst = std::max(worst, border / interior);
  }
  return worst;
}

// How far the edge row stands out: the median |step| from each edge sample
// to its neighbour inside, against the median |step| between rows inside
// (16 cells and more from the edge); the largest of the four sides.
double edge_step(const Heightfield& hf) {
  const int32_t w = hf.width(), h = hf.height(), inner = 16;
  const float* z = hf.data();
  auto median = [](std::vector<float> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return double(v[v.size() / 2]);
  };
  std::vector<float> steps;
  for (int32_t y = inner; y < h - 1 - inner; ++y)
    for (int32_t x = inner; x < w - inner; ++x) steps.push_back(std::fabs(z[size_t(y + 1) * w + x] - z[size_t(y) * w + x]));
  const double interior = median(steps);
  double worst = 0;
  for (int side = 0; side < 4; ++side) {
    const bool row = side < 2;
    const int32_t len = row ? w : h;
    steps.clear();
    for (int32_t k = 1; k < len - 1; ++k) {
      auto at = [&](int32_t depth) {  // the sample `depth` cells in from this side, k along it
        const int32_t x = row ? k : side == 2 ? depth : w - 1 - depth, y = !row ? k : side == 0 ? depth : h - 1 - depth;
        return z[size_t(y) * w + x];
      };
      steps.push_back(std::fabs(at(0) - at(1)));
    }
    worst = std::max(worst, median(steps) / interior);
  }
  return worst;
}

// The most any outlet rose: the edge cells where 50 cells or more of the
// eroded terrain drain (D8 over its filled heights) leave the map, out
// against in.
double highest_outlet_rise(const Heightfield& in, const Heightfield& out) {
  const D8Grid g = grid_of(out, false);
  std::vector<float> z = values(out);
  FlowGraph graph;
  route_filled(g, z.data(), -1, graph);
  std::vector<double> area;
  accumulate_area(g, graph, area);
  double highest = -1e30;
  g.for_each_edge_cell([&](size_t i) {
    if (area[i] >= 50 * g.spacing * g.spacing) highest = std::max(highest, double(out.data()[i] - in.data()[i]));
  });
  return highest;
}

TEST_P(EveryPreset, LeavesTheBorderRowsAsSmoothAsTheInterior) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // Issue 24's demo (fBm 513^2, seed 7): its top rows' p99 |Laplacian| was
  // about twice the interior's. fBm has no edge of its own (the inputs'
  // ratio is 0.99-1.06), so the eroded borders are held to 1.25. Measured
  // 0.98-1.09 at 513^2 for every preset; before the detail run's creep
  // acted on its change only, Rugged Mountains gave 1.65-1.94 at 513^2 (the
  // creep smoothed the interior, and the edge rows are held fixed).
  // At 257^2, the model's own grid, that p99 is a channel's: a valley
  // running along an edge (seed 7's right side has one in its input) holds
  // the band's largest |Laplacian| (1.7-3.5 there), so it is not asserted.
  //
  // The edge row itself: while creep held it fixed at the input's rough
  // heights beside the smoothed rows inside (a one-cell fringe), its median
  // step to the row inside was 1.74-4.03x the interior's median step
  // between rows (fBm seeds 1, 2, 3, 7, at 257^2 and 513^2). With creep
  // closed at the edge it is 0.52-1.47x; the input's own is 1.19. Held to
  // 1.6: above the measured worst and the input's, below every fringe seen.
  //
  // And the outlets stay: creep closed at the edge filled the notches where
  // rivers leave the map from the edge cells beside them (Rugged Mountains,
  // fBm 513^2 seed 1: 66 of 92 outlets rose by over 1 cm, median 2.1 cm) and
  // silted the valleys' mouths; here the highest outlet rose 3.8-7.2 cm.
  // Edge cells that gather water now never rise by creep; the highest
  // outlet rises 0-1.7 cm (deposits and the model's change resampled
  // between its cells). Bound: 2.5 cm.
  for (const int32_t size : {257, 513})
    for (uint64_t seed : {1, 7}) {
      const Heightfield& in = fbm(size, seed);
      const Heightfield out = erode(in, preset_for(GetParam()), nullptr);
      const double before = border_roughness(in), after = border_roughness(out);
      const double outlet_rise = highest_outlet_rise(in, out);
      std::printf("%-16s fbm %d seed %d: border / interior p99 |laplacian| %.3f -> %.3f, edge step %.3f -> %.3f, "
                  "highest outlet rise %.4f\n",
                  GetParam().c_str(), size, int(seed), before, after, edge_step(in), edge_step(out), outlet_rise);
      EXPECT_LE(outlet_rise, 0.025) << GetParam() << " fbm " << size << " seed " << seed;
      if (size > 257) {
        EXPECT_LE(after, 1.25) << GetParam() << " fbm " << size << " seed " << seed;
      }
      EXPECT_LE(edge_step(out), 1.6) << GetParam() << " fbm " << size << " seed " << seed;
    }
}

// The final's samples on the preview's flat floors (filled lakes): the
// preview cells whose 5 x 5 neighbourhood spans under 0.5 mm, and on each
// the final's samples within half a preview cell. Returns how many stand
// more than 4 mm above their cell's median, and the most any stands above.
std::pair<int64_t, double> bumps_on_flat_floors(const Heightfield& preview, const Heightfield& final_hf) {
  const int32_t w = preview.width(), fw = final_hf.width(), f = (fw - 1) / (w - 1);
  const float *p = preview.data(), *z = final_hf.data();
  int64_t count = 0;
  double worst = 0;
  std::vector<float> cell;
  for (int32_t y = 2; y < w - 2; ++y)
    for (int32_t x = 2; x < w - 2; ++x) {
      float lo = p[size_t(y) * w + x], hi = lo;
      for (int32_t dy = -2; dy <= 2; ++dy)
        for (int32_t dx = -2; dx <= 2; ++dx) {
          const float v = p[size_t(y + dy) * w + x + dx];
          lo = std::min(lo, v), hi = std::max(hi, v);
        }
      if (hi - lo >= 5e-4f) continue;
      cell.clear();
      for (int32_t dy = -f / 2; dy <= f / 2; ++dy)
        for (int32_t dx = -f / 2; dx <= f / 2; ++dx) cell.push_back(z[size_t(y * f + dy) * fw + x * f + dx]);
      std::vector<float> sorted = cell;
      std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
      const float median = sorted[sorted.size() / 2];
      for (float v : cell) {
        count += v - median > 4e-3f;
        worst = std::max(worst, double(v - median));
      }
    }
  return {count, worst};
}

TEST_P(EveryPreset, LaysTheFinalsFilledFloorsAsFlatAsThePreviews) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // Seen in the GUI (levels 10, seed 1, Rugged Mountains): 70 pimples of
  // 5-11 mm on a filled lake's floor where the preview (levels 8) is flat.
  // They were the crests of texture the model does not see, left standing
  // when the detail run's lake filled over it (see bury in landscape.cpp):
  // 259 samples of that final stood more than 4 mm above their cell's
  // median there, the highest 9.8 mm. Now the highest on any preset and
  // seed here is 3.4 mm: the input's own texture of a few mm on the plain
  // where the falloff ends (seed 5), detail below the preview's cell that
  // the final keeps by design; on the lakes' floors 1.1 mm. (Broken on
  // purpose: bury about the box mean of z, 50-383 samples on seed 1 of
  // every preset; without its wear, 5 on Rugged Mountains seed 1.) With the
  // detail run's local rules one sample of Rugged Mountains seed 1 stands
  // 5.5 mm out, a crest of the input's texture (9.1 mm above the floor in
  // the input) at a floor's edge, alone: at most 2 such samples, below what
  // either broken variant gives.
  for (uint64_t seed : {1, 5}) {
    const Heightfield preview = erode(default_mountain(8, seed), preset_for(GetParam()), nullptr);
    const Heightfield final_hf = erode(default_mountain(10, seed), preset_for(GetParam()), nullptr);
    const auto [count, worst] = bumps_on_flat_floors(preview, final_hf);
    std::printf("%-16s seed %d: %lld samples stand > 4 mm above the preview's flat floors, the highest %.4f\n",
                GetParam().c_str(), int(seed), static_cast<long long>(count), worst);
    EXPECT_LE(count, 2) << GetParam() << " seed " << seed;
  }
}

// Samples standing more than `high` above all eight neighbours, whose
// neighbours span less than 4 mm (a crest out of a flat floor), 1 cell
// and more from the edge.
int64_t crests_on_flats(const Heightfield& hf, float high) {
  const int32_t w = hf.width(), h = hf.height();
  const float* z = hf.data();
  int64_t count = 0;
  for (int32_t y = 1; y < h - 1; ++y)
    for (int32_t x = 1; x < w - 1; ++x) {
      float lo = 1e30f, hi = -1e30f;
      for (int k = 0; k < 8; ++k) {
        const float v = z[size_t(y + kDy[k]) * w + x + kDx[k]];
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
      count += hi - lo < 4e-3f && z[size_t(y) * w + x] - hi > high;
    }
  return count;
}

TEST_P(EveryPreset, LeavesNoCrestStandingOutOfAPartlyFilledFloor) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // Example 14 (fBm 513^2 seed 7, Rugged Mountains): a lake filled a few
  // mm deep keeps the texture under it, and the detail run's creep on its
  // change lifted crests with the deposit around them (one by 11 mm), so
  // they stood 10-18 mm out of the flat floor. A texture sample beside a
  // deposit now rises no higher than plain creep puts it. Crests over 1 cm
  // out of a flat, seeds 1 and 7 together: 11-31 per preset without that
  // rule, 1-7 with it (what is left stands where a thin fill ends against
  // the rock's texture, a shore's last knob). Bound: 9.
  int64_t crests = 0;
  for (uint64_t seed : {1, 7}) {
    const Heightfield out = erode(fbm(513, seed), preset_for(GetParam()), nullptr);
    const int64_t here = crests_on_flats(out, 0.01f);
    std::printf("%-16s fbm 513 seed %d: %lld crests over 1 cm out of flat floors\n", GetParam().c_str(), int(seed),
                static_cast<long long>(here));
    crests += here;
  }
  EXPECT_LE(crests, 9) << GetParam();
}

// The energy of the finest detail (the terrain less its 5 x 5 smoothing),
// eroded against input, on hillslopes: cells more than 3 cells from any
// cell whose multiple-flow area (on the eroded terrain) exceeds 0.1% of the
// map, and 4 cells from the edge.
double hillslope_detail_kept(const Heightfield& in, const Heightfield& out) {
  const int32_t w = in.width(), h = in.height();
  const D8Grid g = grid_of(out, false);
  std::vector<float> z = values(out);
  FlowGraph graph;
  route_and_fill(g, z.data(), -1, graph);
  std::vector<double> area;
  multiple_flow_area(g, z.data(), -1, area);
  const double map = double(w - 1) * (h - 1) * g.spacing * g.spacing;
  std::vector<uint8_t> near(in.size(), 0);
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      if (!(area[size_t(y) * w + x] > 1e-3 * map)) continue;
      for (int32_t dy = -3; dy <= 3; ++dy)
        for (int32_t dx = -3; dx <= 3; ++dx) {
          const int32_t nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < w && ny < h) near[size_t(ny) * w + nx] = 1;
        }
    }
  const std::vector<float> a = values(in), b = values(out);
  const std::vector<float> sa = smooth(a, w, h, 1), sb = smooth(b, w, h, 1);
  double ea = 0, eb = 0;
  for (int32_t y = 4; y < h - 4; ++y)
    for (int32_t x = 4; x < w - 4; ++x) {
      const size_t i = size_t(y) * w + x;
      if (near[i]) continue;
      ea += double(a[i] - sa[i]) * (a[i] - sa[i]);
      eb += double(b[i] - sb[i]) * (b[i] - sb[i]);
    }
  return eb / ea;
}

TEST_P(EveryPreset, KeepsTheFineDetailOfHillslopes) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "statistical ensemble: Release only";
#endif
  // Issue 24's demo (fBm 513^2) lost its finest detail. On a terrain finer
  // than the model's grid that detail is the rock's texture: erosion may
  // wear it (the stream-power law erodes every cell, gullies may add to
  // it) but not erase it. Before the detail run's creep acted on its change
  // only, and before the model's grid sampled the terrain averaged, 0.4-2.2 %
  // of its energy was kept on hillslopes (Rugged Mountains); now, every
  // preset, 0.38-0.54 at 513^2 and 0.35-0.64 at 1025^2 (seeds 1 and 7; 0.60
  // and 0.88 and more while deposits crept on their change too, which printed
  // the buried bed's texture onto filled flats). The measure is nearly the
  // same on every seed (erosion acts on the texture about linearly, and it
  // sums over 10^5 cells), so the bounds are 0.3 (Scree Slopes, the lowest,
  // less a margin) and 1.5 (no roughening). (At 257^2, the
  // model's own grid, the finest detail is what the model erodes: 3-13 %
  // is kept there, by design.)
  for (const int32_t size : {513, 1025})
    for (uint64_t seed : {1, 7}) {
      const Heightfield& in = fbm(size, seed);
      const Heightfield out = erode(in, preset_for(GetParam()), nullptr);
      const double kept = hillslope_detail_kept(in, out);
      std::printf("%-16s fbm %d seed %d: hillslope detail energy kept %.3f\n", GetParam().c_str(), size, int(seed),
                  kept);
      EXPECT_GE(kept, 0.3) << GetParam() << " fbm " << size << " seed " << seed;
      EXPECT_LE(kept, 1.5) << GetParam() << " fbm " << size << " seed " << seed;
    }
}

// --- Strength and masks -------------------------------------------------

TEST(ErosionModel, StrengthZeroChangesNothingAndMoreStrengthErodesMore) {
  const Heightfield in = default_mountain(8, 1);
  ErosionConfig c = preset_for("rugged_mountains");
  c.model.strength = 0;
  const Heightfield none = erode(in, c, nullptr);
  EXPECT_TRUE(std::equal(none.data(), none.data() + none.size(), in.data()));
  double previous = 0;
  for (double s : {0.25, 0.5, 1.0}) {
    c.model.strength = s;
    const Heightfield out = erode(in, c, nullptr);
    double change = 0;
    for (size_t i = 0; i < in.size(); ++i) change += std::fabs(out.data()[i] - in.data()[i]);
    EXPECT_GT(change, previous) << s;
    previous = change;
  }
}

TEST(ErosionModel, TheMassBudgetIsTheSameBitsOnAnyThreadCount) {
  // The heights never depended on the threads; the volumes did, in their
  // last digits (a reduction over a dynamic schedule adds in the order the
  // chunks happen to run). Several runs on two threads, to give an order
  // that depends on the run a chance to show.
  const Heightfield in = default_mountain(8, 13);
  ErosionConfig c = preset_for("rugged_mountains");
  c.threads = 1;
  MassBudget one;
  erode(in, c, nullptr, &one);
  ASSERT_GT(one.detached, 0.0);
  c.threads = 2;
  for (int run = 0; run < 6; ++run) {
    MassBudget two;
    erode(in, c, nullptr, &two);
    EXPECT_EQ(one.detached, two.detached) << run;
    EXPECT_EQ(one.deposited, two.deposited) << run;
    EXPECT_EQ(one.carried_out, two.carried_out) << run;
  }
}

TEST(ErosionModel, NothingOutsideTheMaskErodesAndMassBalances) {
  // Mask: the left third erodes, the right third not (a 4 x 2 map: its
  // bilinear resampling ramps across the middle third). Diffusion is
  // off so that the volume is exactly bookkept: what the bed lost is what
  // was laid down plus what left at the edges. On 257^2 the model runs on
  // the terrain's own grid, so the budget is of this grid (a smaller
  // terrain is resampled onto the model's grid, whose budget it is).
  const Heightfield in = default_mountain(8, 2);
  const float mask[] = {1, 1, 0, 0, 1, 1, 0, 0};
  for (const char* id : {"rugged_mountains", "alluvial_fans"}) {
    ErosionConfig c = preset_for(id);
    c.fluvial.diffusion = 0;
    c.model.strength = 1;
    c.erosion_mask = {mask, 4, 2};
    MassBudget budget;
    const Heightfield out = erode(in, c, nullptr, &budget);
    const int32_t w = in.width();
    double change = 0, lowered_left = 0;
    for (int32_t y = 0; y < w; ++y)
      for (int32_t x = 0; x < w; ++x) {
        const float d = out.at(x, y) - in.at(x, y);
        change += d;
        if (3 * x >= 2 * (w - 1)) EXPECT_GE(d, 0.0f) << id << " at " << x << ", " << y;  // mask 0: no lowering
        if (x < w / 4) lowered_left += std::min(0.0f, d);
      }
    EXPECT_LT(lowered_left, 0) << id << ": the masked half eroded";
    const double cell = std::pow(grid_of(in, false).spacing, 2);
    EXPECT_GT(budget.detached, 0) << id;
    // Float heights: each cell's change is exact to ~1e-7 of its height.
    EXPECT_NEAR(change * cell, budget.deposited - budget.detached + budget.filled_pits, 1e-5 * budget.detached + 1e-6)
        << id;
    EXPECT_NEAR(budget.detached, budget.deposited + budget.carried_out, 1e-9 * budget.detached) << id;
  }
  // Where the mask is 0 nothing lowers, on a finer grid too (coarse to fine).
  const Heightfield big = default_mountain(9, 2);
  ErosionConfig c = preset_for("badlands");
  c.erosion_mask = {mask, 4, 2};
  const Heightfield out = erode(big, c, nullptr);
  const int32_t w = big.width();
  for (int32_t y = 0; y < w; ++y)
    for (int32_t x = 2 * (w - 1) / 3 + 1; x < w; ++x)
      ASSERT_GE(out.at(x, y), big.at(x, y) - 1e-6f * std::fabs(big.at(x, y))) << x << ", " << y;
}

// A mask of the terrain's own size: 1 left of column `edge`, 0 from it on.
std::vector<float> left_of(int32_t edge, int32_t w, int32_t h) {
  std::vector<float> m(size_t(w) * h, 0.0f);
  for (int32_t y = 0; y < h; ++y) std::fill_n(m.begin() + size_t(y) * w, edge, 1.0f);
  return m;
}

TEST(ErosionModel, CreepUnderTheMaskKeepsTheVolume) {
  // With creep on: a 5 x 5 mask, 0 on its border (so 0 on the terrain's
  // edge cells: no creep flows out there) and its right two columns, 1 in
  // the middle of the left half, ramps between. Creep moves material along
  // each edge by D x the smaller of its cells' weights, so it makes and
  // loses none, and the budget balances as without creep. (While the mask
  // scaled creep's lowering only, the land kept 0.8 world units^3 more than
  // the budget, of 18 to 26 detached.) At 257^2, where the model's grid,
  // whose budget it is, is the terrain's own.
  const Heightfield in = default_mountain(8, 2);
  const float mask[] = {0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0};
  for (const char* id : {"rugged_mountains", "gentle_valleys"}) {
    ErosionConfig c = preset_for(id);
    ASSERT_GT(c.fluvial.diffusion, 0) << id;
    c.model.strength = 1;
    c.erosion_mask = {mask, 5, 5};
    MassBudget budget;
    const Heightfield out = erode(in, c, nullptr, &budget);
    double change = 0;
    for (size_t i = 0; i < in.size(); ++i) change += out.data()[i] - in.data()[i];
    const double cell = std::pow(grid_of(in, false).spacing, 2);
    EXPECT_GT(budget.detached, 0) << id;
    EXPECT_NEAR(change * cell, budget.deposited - budget.detached + budget.filled_pits, 1e-5 * budget.detached + 1e-6)
        << id;
  }
}

TEST(ErosionModel, WhereNoSedimentComesTheMaskedOffLandStaysAsItWas) {
  // fBm whose right half, masked off, is a plateau 3 world units above the
  // left: the sediment of the left half cannot climb to it, and nothing on
  // it erodes. With creep acting only where the mask lets it, every height
  // there stays as it was, bit for bit, resampled onto the model's grid
  // (129^2) and coarse to fine (513^2: the model's change resampled onto it carries
  // only deposits outside the mask, and there are none here). (While the
  // mask scaled creep's lowering only, creep filled the plateau's hollows:
  // 70 % of its cells changed at 129^2, 90 % at 513^2.)
  for (const int32_t size : {129, 513}) {
    Heightfield in = make_fbm(size, 5);
    for (int32_t y = 0; y < size; ++y)
      for (int32_t x = size / 2; x < size; ++x) in.at(x, y) += 3.0f;
    const std::vector<float> mask = left_of(size / 2, size, size);
    ErosionConfig c = preset_for("rugged_mountains");
    c.model.strength = 1;
    c.erosion_mask = {mask.data(), size, size};
    const Heightfield out = erode(in, c, nullptr);
    size_t changed = 0, lowered_left = 0;
    for (int32_t y = 0; y < size; ++y)
      for (int32_t x = 0; x < size; ++x) {
        if (x >= size / 2) changed += out.at(x, y) != in.at(x, y);
        if (x < size / 2) lowered_left += out.at(x, y) < in.at(x, y);
      }
    EXPECT_GT(lowered_left, size_t(size) * size / 4) << size << ": the left half erodes";
    EXPECT_EQ(changed, 0u) << size << ": cells of the plateau that changed";
  }
}

TEST(ErosionModel, TheModelsCreepIsNotResampledOutsideTheMask) {
  // Coarse to fine (513^2), with no rain and the talus at its steepest:
  // only creep acts. The mask is 1 up to column 256 and 0 from 257 on; the
  // model's node 128 (column 256) creeps, and the model's change, resampled,
  // blurs half of it onto column 257, outside the mask, where it may carry
  // deposits only. So where the mask is 0 nothing changes (0 here; the bound
  // allows for the float rounding of the model's change less its creep,
  // 1e-7 of the heights). (When creep's rise was resampled unscaled, column
  // 257 rose by up to 0.12.)
  const Heightfield in = default_mountain(9, 1);
  const int32_t w = in.width();
  const std::vector<float> mask = left_of(w / 2 + 1, w, w);
  const float dry[] = {0, 0, 0, 0};
  ErosionConfig c = preset_for("gentle_valleys");
  c.model.strength = 1;
  c.thermal.talus_degrees = 89;
  c.rain_map = {dry, 2, 2};
  c.erosion_mask = {mask.data(), w, w};
  const Heightfield out = erode(in, c, nullptr);
  double largest = 0, moved_inside = 0;
  for (int32_t y = 0; y < w; ++y)
    for (int32_t x = 0; x < w; ++x) {
      const double d = std::fabs(out.at(x, y) - in.at(x, y));
      (x > w / 2 ? largest : moved_inside) = std::max(x > w / 2 ? largest : moved_inside, d);
    }
  EXPECT_GT(moved_inside, 1e-3) << "creep acts inside the mask";
  EXPECT_LE(largest, 1e-6) << "outside the mask";
}

TEST(ErosionModel, TheMaskedOffHalfOfTheDefaultMountainRisesOnlyWhereSedimentLands) {
  // docs/erosion.md's Blender case: the add-on's default mountain, Rugged
  // Mountains, the mask on its left half. Sediment from the left settles on
  // the right (in the hollow at its top, along its channels); nothing else
  // there changes. 5.9 % of the right half rises by over 1 mm (61 % while
  // creep filled every hollow there), so at most 15 %; nothing lowers.
  const Heightfield in = default_mountain(8, 1);
  const int32_t w = in.width();
  const std::vector<float> mask = left_of(w / 2, w, w);
  ErosionConfig c = preset_for("rugged_mountains");
  c.erosion_mask = {mask.data(), w, w};
  const Heightfield out = erode(in, c, nullptr);
  size_t risen = 0, right = 0;
  for (int32_t y = 0; y < w; ++y)
    for (int32_t x = w / 2 + 2; x < w; ++x) {
      const float d = out.at(x, y) - in.at(x, y);
      ASSERT_GE(d, 0.0f) << x << ", " << y;
      risen += d > 1e-3f, ++right;
    }
  std::printf("default mountain, mask on the left half: %.1f %% of the right half rose by over 1 mm\n",
              100.0 * double(risen) / double(right));
  EXPECT_LE(double(risen), 0.15 * double(right));
}

TEST(ErosionModel, NoRainNoRivers) {
  // A rain map of zeros: no water, so no detachment by rivers. With the
  // talus at its steepest and no creep nothing else acts: the terrain stays.
  const Heightfield in = default_mountain(8, 4);
  const float dry[] = {0, 0, 0, 0};
  ErosionConfig c = preset_for("badlands");
  c.thermal.talus_degrees = 89;
  c.fluvial.diffusion = 0;
  c.rain_map = {dry, 2, 2};
  const Heightfield out = erode(in, c, nullptr);
  for (size_t i = 0; i < in.size(); ++i) ASSERT_EQ(out.data()[i], in.data()[i]) << i;
  c.rain_map = {};
  const Heightfield wet = erode(in, c, nullptr);
  EXPECT_FALSE(std::equal(wet.data(), wet.data() + wet.size(), in.data()));
}

TEST(ErosionModel, BadMapsAndStrengthGetAClearError) {
  const Heightfield in = default_mountain(6, 1);
  auto message = [&](ErosionConfig c) -> std::string {
    try {
      erode(in, c, nullptr);
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), FT_ERR_INVALID_ARGUMENT);
      return e.what();
    }
    return "accepted";
  };
  const float nan_mask[] = {1, NAN, 1, 1}, big[] = {1, 2, 1, 1};
  ErosionConfig c = preset_for("gentle_valleys");
  c.erosion_mask = {nan_mask, 2, 2};
  EXPECT_NE(message(c).find("erosion_mask's values must be in [0, 1]; sample 1, 0 is "), std::string::npos)
      << message(c);
  c = preset_for("gentle_valleys");
  c.rain_map = {big, 2, 2};
  EXPECT_NE(message(c).find("rain_map's values must be in [0, 1]"), std::string::npos) << message(c);
  c = preset_for("gentle_valleys");
  c.rain_map = {big, 1, 4};
  EXPECT_NE(message(c).find("rain_map_width must be in 2..65536"), std::string::npos) << message(c);
  for (double s : {-0.1, 1.5, double(NAN)}) {
    c = preset_for("gentle_valleys");
    c.model.strength = s;
    EXPECT_NE(message(c).find("strength must be in [0, 1]"), std::string::npos) << message(c);
  }
}

TEST(ErosionModel, PresetsAnswerToIdLabelAndOldName) {
  for (const auto& p : erosion_presets()) {
    const ErosionConfig a = erosion_preset(p.id), b = erosion_preset(p.label);
    EXPECT_EQ(a.fluvial.erodibility, b.fluvial.erodibility) << p.id;
    EXPECT_GT(a.model.duration, 0) << p.id;
    if (!p.alias.empty()) EXPECT_EQ(erosion_preset(p.alias).fluvial.erodibility, a.fluvial.erodibility) << p.id;
  }
  EXPECT_EQ(erosion_preset("valleys").fluvial.erodibility, erosion_preset("Gentle Valleys").fluvial.erodibility);
  EXPECT_EQ(erosion_preset("land").fluvial.erodibility, erosion_preset("rugged_mountains").fluvial.erodibility);
  try {
    erosion_preset("glaciers");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("gentle_valleys (or valleys)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ft::erosion
