// SPDX-License-Identifier: GPL-3.0-or-later
// Landforms (terrain/landform.hpp): levelling, height offset, edge falloff
// and the sea, applied to every method's heights; windows of a terrain with
// landforms equal the whole bit for bit; a sea given as a fraction is
// refused for windows; bad values are refused by the parameter table.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "terrain/terrain.hpp"
#include "tiles/manifest.hpp"

using namespace ft;

namespace {

ft_terrain_params params(int method, int levels = 7) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = method;
  p.levels = levels;
  p.width = p.height = (1 << levels) + 1;
  p.seed = 5;
  p.threads = 2;
  return p;
}

std::string refusal(const ft_terrain_params& p, bool window = false) {
  try {
    if (window) terrain::generate_terrain_window(p, 0, 0, 0, 3, 3);
    else terrain::generate_terrain(p);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

double at(const Heightfield& hf, int i, int j) { return hf.data()[size_t(j) * size_t(hf.width()) + size_t(i)]; }

}  // namespace

TEST(Landform, DefaultsLeaveTheMethodsHeightsUntouched) {
  // The new fields' defaults are neutral, so every terrain made before them is unchanged.
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
  p.falloff_width = 0.5, p.sea_level = 3, p.edge_level = -2, p.sea_fraction = 0.6;  // unused while off
  const Heightfield a = terrain::generate_terrain(p), b = terrain::generate_terrain(params(FT_TERRAIN_MIDPOINT));
  ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

TEST(Landform, LevellingRemovesTheCornerPlane) {
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
  const Heightfield raw = terrain::generate_terrain(p);
  p.levelling = 1;
  const Heightfield level = terrain::generate_terrain(p);
  const int n = raw.width() - 1;
  for (auto [i, j] : {std::pair{0, 0}, {n, 0}, {0, n}, {n, n}}) EXPECT_EQ(at(level, i, j), 0.0) << i << ", " << j;
  // An inside sample: its height minus the bilinear surface through the corners.
  const double c00 = at(raw, 0, 0), c10 = at(raw, n, 0), c01 = at(raw, 0, n), c11 = at(raw, n, n);
  const double u = 37.0 / n, v = 90.0 / n;
  const double plane = (1 - v) * ((1 - u) * c00 + u * c10) + v * ((1 - u) * c01 + u * c11);
  EXPECT_NEAR(at(level, 37, 90), at(raw, 37, 90) - plane, 1e-5);
  // Half the levelling removes half the plane.
  p.levelling = 0.5;
  EXPECT_NEAR(at(terrain::generate_terrain(p), 37, 90), at(raw, 37, 90) - 0.5 * plane, 1e-5);
}

TEST(Landform, OffsetMovesEverySample) {
  ft_terrain_params p = params(FT_TERRAIN_FBM);
  const Heightfield raw = terrain::generate_terrain(p);
  p.height_offset = 2.5;
  const Heightfield up = terrain::generate_terrain(p);
  for (size_t k = 0; k < raw.size(); k += 97) EXPECT_NEAR(up.data()[k], raw.data()[k] + 2.5, 1e-6);
}

TEST(Landform, SquareFalloffReachesTheEdgeLevelOnEveryEdge) {
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
  const Heightfield raw = terrain::generate_terrain(p);
  p.falloff = FT_FALLOFF_SQUARE, p.falloff_width = 0.25, p.edge_level = -1.5;
  const Heightfield fall = terrain::generate_terrain(p);
  const int n = raw.width() - 1;
  for (int k = 0; k <= n; ++k) {
    EXPECT_EQ(at(fall, k, 0), float(-1.5));
    EXPECT_EQ(at(fall, k, n), float(-1.5));
    EXPECT_EQ(at(fall, 0, k), float(-1.5));
    EXPECT_EQ(at(fall, n, k), float(-1.5));
  }
  // Beyond the band (more than 0.25 of the half width from every edge: 16 samples here) nothing moves.
  for (int j = 17; j < n - 16; j += 5)
    for (int i = 17; i < n - 16; i += 3) ASSERT_EQ(at(fall, i, j), at(raw, i, j)) << i << ", " << j;
  // Inside the band heights lie between the edge level and the raw height.
  const double r = at(raw, 8, 64), f = at(fall, 8, 64);
  EXPECT_LE(std::fabs(f + 1.5), std::fabs(r + 1.5));
  EXPECT_NE(f, r);
}

TEST(Landform, RadialFalloffMakesAnIsland) {
  ft_terrain_params p = params(FT_TERRAIN_FBM);
  const Heightfield raw = terrain::generate_terrain(p);
  p.falloff = FT_FALLOFF_RADIAL, p.falloff_width = 0.5, p.edge_level = -1;
  const Heightfield island = terrain::generate_terrain(p);
  const int n = raw.width() - 1, c = n / 2;
  // The corners and the edges' midpoints are at the edge level; the centre is untouched.
  for (auto [i, j] : {std::pair{0, 0}, {n, n}, {c, 0}, {0, c}, {n, c}, {c, n}})
    EXPECT_EQ(at(island, i, j), float(-1)) << i << ", " << j;
  EXPECT_EQ(at(island, c, c), at(raw, c, c));
  EXPECT_EQ(at(island, c + 10, c - 12), at(raw, c + 10, c - 12));  // well inside half the radius
}

TEST(Landform, SeaAtAHeightFlattensTheLowGround) {
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
  const Heightfield raw = terrain::generate_terrain(p);
  const HeightStats s = raw.stats();
  p.sea = FT_SEA_HEIGHT, p.sea_level = 0.5 * (s.min + s.max);
  const Heightfield sea = terrain::generate_terrain(p);
  const float level = float(p.sea_level);
  size_t flat = 0;
  for (size_t k = 0; k < raw.size(); ++k) {
    ASSERT_EQ(sea.data()[k], std::max(raw.data()[k], level));
    flat += sea.data()[k] == level;
  }
  EXPECT_GT(flat, 0u);
  EXPECT_LT(flat, raw.size());
}

TEST(Landform, SeaAsAFractionCoversThatShareForEverySeed) {
  // The complaint: a sea level in metres floods one seed and misses
  // the next. A fraction q covers floor(q n) + 1 samples (the quantile's
  // sample and those below it; heights are continuous, so ties have
  // probability 0) whatever the seed's height range.
  for (uint64_t seed : {1, 2, 3, 4}) {
    ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
    p.seed = seed;
    p.sea = FT_SEA_FRACTION, p.sea_fraction = 0.3;
    const Heightfield sea = terrain::generate_terrain(p);
    const float level = sea.stats().min;
    const size_t flat = size_t(std::count(sea.data(), sea.data() + sea.size(), level));
    EXPECT_EQ(flat, size_t(0.3 * double(sea.size())) + 1) << "seed " << seed;
  }
}

TEST(Landform, CustomMaskIsResampledBilinearlyOverTheWholeTerrain) {
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);  // 129 x 129
  const Heightfield raw = terrain::generate_terrain(p);
  // 3 x 2: columns at u = 0, 0.5, 1; rows at v = 0, 1.
  const std::vector<float> mask = {0.0f, 0.5f, 1.0f,  //
                                   1.0f, 0.25f, 0.0f};
  p.falloff = FT_FALLOFF_CUSTOM, p.edge_level = -1.5;
  p.falloff_mask = mask.data(), p.falloff_mask_width = 3, p.falloff_mask_height = 2;
  const Heightfield masked = terrain::generate_terrain(p);
  auto expect = [&](int i, int j, double m) {
    EXPECT_NEAR(at(masked, i, j), -1.5 + m * (at(raw, i, j) + 1.5), 1e-5) << i << ", " << j << " mask " << m;
  };
  expect(0, 0, 0.0), expect(64, 0, 0.5), expect(128, 0, 1.0), expect(0, 128, 1.0), expect(128, 128, 0.0);
  EXPECT_EQ(at(masked, 128, 0), at(raw, 128, 0));  // weight 1: exactly the height
  EXPECT_EQ(at(masked, 0, 0), -1.5f);              // weight 0: exactly the edge level
  // Inside: u = 32/128 (between columns 0 and 1 at 0.5), v = 96/128.
  const double top = 0.5 * 0.0 + 0.5 * 0.5, bottom = 0.5 * 1.0 + 0.5 * 0.25;
  expect(32, 96, 0.25 * top + 0.75 * bottom);
  // A mask of ones changes nothing.
  const std::vector<float> ones(16, 1.0f);
  p.falloff_mask = ones.data(), p.falloff_mask_width = 4, p.falloff_mask_height = 4;
  const Heightfield same = terrain::generate_terrain(p);
  ASSERT_EQ(std::memcmp(same.data(), raw.data(), raw.size() * sizeof(float)), 0);
}

TEST(Landform, BadFalloffMasksAreRefused) {
  std::vector<float> mask(4 * 3, 0.5f);
  auto with = [&](auto change) {
    ft_terrain_params p = params(FT_TERRAIN_FBM, 5);
    p.falloff = FT_FALLOFF_CUSTOM;
    p.falloff_mask = mask.data(), p.falloff_mask_width = 4, p.falloff_mask_height = 3;
    change(p);
    return refusal(p);
  };
  EXPECT_EQ(with([](auto&) {}), "no error");
  EXPECT_NE(with([](auto& p) { p.falloff_mask = nullptr; }).find("needs a mask"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.falloff_mask_width = 1; }).find("falloff_mask_width must be in 2..65536"),
            std::string::npos);
  EXPECT_NE(with([](auto& p) { p.falloff_mask_height = 0; }).find("falloff_mask_height"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.falloff_mask_height = 70000; }).find("falloff_mask_height"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.falloff_mask_width = -3; }).find("falloff_mask_width"), std::string::npos);
  for (float bad : {NAN, -0.01f, 1.01f, INFINITY}) {
    mask[6] = bad;
    const std::string why = with([](auto&) {});
    EXPECT_NE(why.find("must be in [0, 1]"), std::string::npos) << bad << ": " << why;
    EXPECT_NE(why.find("sample 2, 1"), std::string::npos) << why;
  }
  mask[6] = 0.5f;
  // Without the custom falloff the mask is not read at all (another falloff, or none).
  EXPECT_EQ(with([](auto& p) { p.falloff = FT_FALLOFF_RADIAL, p.falloff_mask = nullptr; }), "no error");
}

TEST(Landform, WindowsWithLandformsEqualTheWholeBitForBit) {
  // A 7 x 5 mask with a value per node, not a multiple of the terrain's grid.
  std::vector<float> mask(7 * 5);
  for (size_t k = 0; k < mask.size(); ++k) mask[k] = float((k * 37) % 11) / 10.0f;
  for (int method : {FT_TERRAIN_MIDPOINT, FT_TERRAIN_FBM, FT_TERRAIN_INTERPOLATED}) {
    for (int falloff : {FT_FALLOFF_SQUARE, FT_FALLOFF_RADIAL, FT_FALLOFF_CUSTOM}) {
      ft_terrain_params p = params(method, 9);
      p.levelling = 0.75, p.height_offset = 0.3, p.falloff = falloff, p.falloff_width = 0.4;
      p.falloff_mask = mask.data(), p.falloff_mask_width = 7, p.falloff_mask_height = 5;
      p.edge_level = -0.7, p.sea = FT_SEA_HEIGHT, p.sea_level = -0.2;
      const Heightfield whole = terrain::generate_terrain(p);
      const int w = whole.width();
      for (auto [x0, y0, ww, wh] : {std::array<int, 4>{0, 0, 1, 1}, {w - 1, w - 1, 1, 1}, {0, 0, 101, 37},
                                    {w - 77, 3, 77, 150}, {201, w - 65, 99, 65}, {0, 255, w, 3}}) {
        const Heightfield part = terrain::generate_terrain_window(p, 0, x0, y0, ww, wh);
        for (int j = 0; j < wh; ++j)
          ASSERT_EQ(std::memcmp(part.data() + size_t(j) * size_t(ww),
                                whole.data() + size_t(y0 + j) * size_t(w) + size_t(x0), size_t(ww) * sizeof(float)),
                    0)
              << "method " << method << " falloff " << falloff << " window " << x0 << ", " << y0 << " row " << j;
      }
      if (method == FT_TERRAIN_MIDPOINT) {  // a coarser level of detail: every 4th sample of the whole
        const Heightfield lod = terrain::generate_terrain_window(p, 2, 0, 0, 129, 129);
        for (int j = 0; j < 129; j += 7)
          for (int i = 0; i < 129; ++i) ASSERT_EQ(at(lod, i, j), at(whole, 4 * i, 4 * j)) << i << ", " << j;
      }
    }
  }
}

TEST(Landform, TileSetsTellTerrainsWithOtherMasksApart) {
  // A tile set reuses tiles only for the same terrain: the mask is part of it.
  std::vector<float> a(9, 0.5f), same = a, other = a;
  other[4] = 0.25f;
  auto identity = [](const std::vector<float>& mask) {
    ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
    p.falloff = FT_FALLOFF_CUSTOM, p.falloff_mask = mask.data(), p.falloff_mask_width = p.falloff_mask_height = 3;
    return tiles::terrain_identity(p);
  };
  EXPECT_EQ(identity(a), identity(same));  // the content counts, not where it lies
  EXPECT_NE(identity(a), identity(other));
  EXPECT_TRUE(identity(a).contains("falloff_mask"));
}

TEST(Landform, SeaFractionIsRefusedForWindows) {
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT);
  p.sea = FT_SEA_FRACTION;
  EXPECT_NE(refusal(p, true).find("sea 'fraction'"), std::string::npos) << refusal(p, true);
  EXPECT_EQ(refusal(p), "no error");
}

TEST(Landform, BadValuesAreRefusedByTheTable) {
  auto with = [](auto change) {
    ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, 4);
    change(p);
    return refusal(p);
  };
  EXPECT_NE(with([](auto& p) { p.levelling = 1.5; }).find("levelling"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.falloff = 4; }).find("falloff"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.falloff_width = 0; }).find("falloff_width"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.edge_level = NAN; }).find("edge_level"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.height_offset = 1e31; }).find("height_offset"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.sea = 7; }).find("sea"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.sea_fraction = 1; }).find("sea_fraction"), std::string::npos);
  EXPECT_NE(with([](auto& p) { p.sea_level = INFINITY; }).find("sea_level"), std::string::npos);
}
