// SPDX-License-Identifier: GPL-3.0-or-later
// The drainage area of large terrains by pieces (erosion/block_drainage.hpp),
// taken here on 1025^2 terrains by smaller settings in the same proportions
// to the model's cell as the defaults at 8193^2 (blocks of 64 model cells,
// a halo of 8): every window and tile is the whole's bits, and the pieces'
// area follows the whole grid's multiple-flow area with no seam at the lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "erosion/block_drainage.hpp"
#include "erosion/erosion.hpp"
#include "io/heightfield_io.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "terrain/terrain.hpp"

using namespace ft;

namespace {

// 1025^2: the model's cell is 4 samples; a halo of 64 is the defaults' 16
// model cells (512 at 8193^2); blocks of 256 (64 cells, half the
// defaults') put 3 lines across, 9 crossings. Wider than 513 drains by pieces.
constexpr erosion::DrainageBlocks kSmall{256, 64, 513};
constexpr int32_t kBlock = 256;

class ScopedBlocks {
 public:
  explicit ScopedBlocks(const erosion::DrainageBlocks& b) : saved_(erosion::drainage_blocks()) {
    erosion::set_drainage_blocks(b);
  }
  ~ScopedBlocks() { erosion::set_drainage_blocks(saved_); }

 private:
  erosion::DrainageBlocks saved_;
};

struct Case {
  std::string name;
  ft_terrain_params terrain;
};

// Midpoint levels 10, seed 13, sea at 0 (a fifth or so of the samples, in
// several seas), bounded or a torus.
Case sea_case(bool periodic) {
  Case c{periodic ? "periodic with a sea" : "bounded with a sea", terrain::default_terrain_params()};
  c.terrain.method = FT_TERRAIN_MIDPOINT;
  c.terrain.levels = 10;
  c.terrain.seed = 13;
  c.terrain.periodic = periodic ? 1 : 0;
  c.terrain.falloff = FT_FALLOFF_NONE;
  c.terrain.sea = FT_SEA_HEIGHT;
  c.terrain.sea_level = 0.0;
  c.terrain.threads = 2;
  return c;
}

ft_build_params params_of(const Case& c, int32_t threads) {
  ft_build_params b = defaults_of<ft_build_params>(pipeline::build_param_table());
  b.terrain = &c.terrain;
  b.erosion_preset = FT_EROSION_PRESET_LAND;
  b.threads = threads;
  return b;
}

struct Rect {
  int64_t x0, y0;
  int32_t w, h;
};

// The first sample where `win` differs from those samples of `whole`, or "".
std::string first_difference(const Heightfield& whole, const Heightfield& win, const Rect& r) {
  if (win.width() != r.w || win.height() != r.h) return "the window's size";
  for (int32_t y = 0; y < r.h; ++y)
    for (int32_t x = 0; x < r.w; ++x) {
      const float a = whole.at(int32_t(r.x0 + x), int32_t(r.y0 + y)), b = win.at(x, y);
      if (std::memcmp(&a, &b, sizeof a) != 0)
        return "sample " + std::to_string(r.x0 + x) + ", " + std::to_string(r.y0 + y) + ": " + std::to_string(b) +
               " instead of " + std::to_string(a);
    }
  return "";
}

// Odd windows: single samples on a line and a crossing, a line's column, a
// rectangle across two lines, one inside a block, the corners; then a tile
// set's tiles of 512 cells (513 samples, sharing their edge samples).
std::vector<Rect> windows(int32_t n) {
  std::vector<Rect> out = {{kBlock, kBlock, 1, 1},  {kBlock, 77, 1, 300},      {200, 3 * kBlock - 5, 700, 11},
                           {0, 0, 37, 53},          {n - 61, n - 29, 61, 29},  {301, 402, 123, 97},
                           {kBlock - 3, 2 * kBlock - 2, 2 * kBlock + 9, 5}};
  for (int32_t y = 0; y < n - 1; y += 512)
    for (int32_t x = 0; x < n - 1; x += 512) out.push_back({x, y, 513, 513});
  return out;
}

void expect_windows_equal_the_whole(const Case& c) {
  const ScopedBlocks blocks(kSmall);
  erosion::ErosionMaps whole_maps;
  const Heightfield whole = pipeline::build_terrain(params_of(c, 2), &whole_maps);
  const int32_t n = whole.width();
  // The case has its sea (else the sea's rule is not seen).
  int64_t sea = 0;
  for (size_t i = 0; i < whole.size(); ++i) sea += whole.data()[i] <= 0.0f;
  ASSERT_GT(sea, int64_t(whole.size() / 20)) << c.name;
  int k = 0;
  for (const Rect& r : windows(n)) {
    const int32_t threads = 1 + k++ % 2;  // the bits never depend on them
    erosion::ErosionMaps maps;
    const Heightfield win = pipeline::build_terrain_window(params_of(c, threads), r.x0, r.y0, r.w, r.h, &maps);
    const std::string where = c.name + ", window " + std::to_string(r.x0) + ", " + std::to_string(r.y0) + " + " +
                              std::to_string(r.w) + " x " + std::to_string(r.h);
    EXPECT_EQ(first_difference(whole, win, r), "") << where << ", heights";
    const auto want = whole_maps.all(), got = maps.all();
    for (size_t m = 0; m < want.size(); ++m) EXPECT_EQ(first_difference(*want[m], *got[m], r), "") << where << ", map " << m;
  }
}

TEST(BlockDrainage, WindowsAndTilesAreTheWholesBitsOnABoundedTerrainWithASea) {
  expect_windows_equal_the_whole(sea_case(false));
}

TEST(BlockDrainage, WindowsAndTilesAreTheWholesBitsOnATorusWithASea) { expect_windows_equal_the_whole(sea_case(true)); }

TEST(BlockDrainage, PiecesAlongAnAxisCutAtTheLines) {
  const ScopedBlocks blocks(kSmall);
  // Bounded 1025: lines at 256, 512, 768 (the last block takes the rest).
  const auto b = erosion::drainage_spans(1025, false);
  ASSERT_EQ(b.size(), 7u);
  EXPECT_EQ(b[0].lo, 0); EXPECT_EQ(b[0].len, 256);
  EXPECT_EQ(b[1].lo, 256); EXPECT_EQ(b[1].len, 1);
  EXPECT_EQ(b[6].lo, 769); EXPECT_EQ(b[6].len, 256);
  // A torus of 1024: a line at 0 too.
  const auto p = erosion::drainage_spans(1024, true);
  ASSERT_EQ(p.size(), 8u);
  EXPECT_EQ(p[0].lo, 0); EXPECT_EQ(p[0].len, 1);
  EXPECT_EQ(p[7].lo, 769); EXPECT_EQ(p[7].len, 255);
  // At or under the whole's side, and a torus whose regions would wrap onto themselves, drain whole.
  erosion::D8Grid g;
  g.width = g.height = 513;
  EXPECT_FALSE(erosion::drains_by_blocks(g));
  g.width = g.height = 1025;
  EXPECT_TRUE(erosion::drains_by_blocks(g));
  g.periodic = true, g.width = 1024, g.height = 300;
  EXPECT_FALSE(erosion::drains_by_blocks(g));
}

// The pieces' area against the whole grid's multiple-flow area (the
// defaults drain 1025^2 as one) on the same eroded terrain, over the land.
struct Agreement {
  double correlation;  // of log10 area
  double within_2x;    // share of the samples within a factor 2
  double channels_10;  // share of the channels (1000 cells or more) within 10%
  double rivers_2x;    // share of the rivers (10^4 cells or more) within a factor 2
  double seam_pieces, seam_whole;  // mean |log step| across lines over off them
};

Agreement agreement_of(const Case& c) {
  erosion::ErosionMaps global_maps, piece_maps;
  const Heightfield whole = pipeline::build_terrain(params_of(c, 2), &global_maps);
  {
    const ScopedBlocks blocks(kSmall);
    const Heightfield again = pipeline::build_terrain(params_of(c, 2), &piece_maps);
    EXPECT_EQ(first_difference(whole, again, {0, 0, whole.width(), whole.height()}), "");
  }
  const int32_t n = whole.width();
  const float* a = global_maps.drainage_area.data();
  const float* b = piece_maps.drainage_area.data();
  if (const char* dir = std::getenv("FT_BLOCK_DRAINAGE_DUMP")) {
    // For looking at (docs/measurements/scale.md renders them).
    const std::string stem = std::string(dir) + "/" + (c.terrain.sea == FT_SEA_NONE ? "land" : "sea");
    io::write_heightfield(global_maps.drainage_area, stem + "_whole.npy");
    io::write_heightfield(piece_maps.drainage_area, stem + "_pieces.npy");
  }
  const bool sea = c.terrain.sea != FT_SEA_NONE;
  auto land = [&](size_t i) { return !sea || whole.data()[i] > 0.0f; };
  const double cell = *std::min_element(a, a + whole.size());  // a sample's own area
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, cnt = 0, within2 = 0, ch = 0, ch10 = 0, rv = 0, rv2 = 0;
  for (size_t i = 0; i < whole.size(); ++i) {
    if (!land(i)) continue;
    const double la = std::log10(a[i]), lb = std::log10(b[i]);
    sa += la, sb += lb, saa += la * la, sbb += lb * lb, sab += la * lb, ++cnt;
    const bool close2 = std::fabs(la - lb) <= std::log10(2.0);
    within2 += close2;
    if (a[i] >= 1000 * cell) ++ch, ch10 += std::fabs(b[i] / a[i] - 1) <= 0.1;
    if (a[i] >= 10000 * cell) ++rv, rv2 += close2;
  }
  const double cov = sab / cnt - sa / cnt * sb / cnt;
  Agreement g;
  g.correlation = cov / std::sqrt((saa / cnt - sa / cnt * sa / cnt) * (sbb / cnt - sb / cnt * sb / cnt));
  g.within_2x = within2 / cnt, g.channels_10 = ch10 / ch, g.rivers_2x = rv2 / rv;
  // Seams: mean |log area step| between neighbours across a line (one of
  // them on it) against the same off the lines, both directions; a seam
  // shows as a ratio above the whole grid's own.
  auto seam_ratio = [&](const float* area) {
    double across = 0, inside = 0, na = 0, ni = 0;
    auto on_line = [](int32_t v) { return v > 0 && v % kBlock == 0 && v < 1024; };
    for (int32_t y = 0; y < n; ++y)
      for (int32_t x = 0; x + 1 < n; ++x)
        for (int dir = 0; dir < 2; ++dir) {
          // (x, y) -> (x + 1, y), and the transposed step (y, x) -> (y, x + 1).
          const size_t i = dir ? size_t(x) * n + y : size_t(y) * n + x, j = dir ? size_t(x + 1) * n + y : i + 1;
          if (!land(i) || !land(j)) continue;
          const double d = std::fabs(std::log10(area[i]) - std::log10(area[j]));
          if (on_line(x) || on_line(x + 1)) across += d, ++na;
          else inside += d, ++ni;
        }
    return (across / na) / (inside / ni);
  };
  g.seam_pieces = seam_ratio(b), g.seam_whole = seam_ratio(a);
  std::printf("%s: log-area correlation %.5f, within 2x %.5f, channels within 10%% %.4f (%.0f), rivers within 2x "
              "%.4f (%.0f), seam ratio %.4f (the whole grid's %.4f)\n",
              c.name.c_str(), g.correlation, g.within_2x, g.channels_10, ch, g.rivers_2x, rv, g.seam_pieces,
              g.seam_whole);
  return g;
}

// Thresholds from the measured values (docs/measurements/scale.md), land
// and sea cases: the code as it is gives correlation and within-2x 1.0000
// (5 digits), channels and rivers 1.0000, a seam ratio within 0.0001 of
// the whole grid's. Broken on purpose: without the coarse inflow the
// correlation is 0.9979 / 0.9996 and 47% / 73% of the rivers are within 2x;
// without the walls 85% of the rivers; lines drained from a halo of 2
// instead of their own give a seam ratio of 1.19 / 1.15 against the whole's
// 1.03 / 1.02. The bounds sit between, well clear of the code's values.
TEST(BlockDrainage, PiecesFollowTheWholeGridsAreaWithNoSeam) {
  Case land = sea_case(false);
  land.name = "bounded land", land.terrain.sea = FT_SEA_NONE;
  for (const Case& c : {land, sea_case(false)}) {
    const Agreement g = agreement_of(c);
    EXPECT_GT(g.correlation, 0.999) << c.name;
    EXPECT_GT(g.within_2x, 0.999) << c.name;
    EXPECT_GT(g.channels_10, 0.99) << c.name;
    EXPECT_GT(g.rivers_2x, 0.98) << c.name;
    // A seam would raise the step across the lines over the whole grid's.
    EXPECT_LT(g.seam_pieces, g.seam_whole * 1.02) << c.name;
  }
}

}  // namespace
