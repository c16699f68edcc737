// SPDX-License-Identifier: GPL-3.0-or-later
// Windows of a terrain (terrain/window.hpp, generate_terrain_window): any
// window equals the same samples of the whole terrain, bit for bit, for
// every method that has windows, plain, periodic and from a reference grid;
// levels of detail are the whole's every 2^lod-th sample; bad windows are
// refused with a message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "terrain/terrain.hpp"
#include "terrain/window.hpp"

using namespace ft;

namespace {

ft_terrain_params params(int method, uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = method;
  p.levels = 12;  // 4097^2
  p.width = p.height = 4097;
  p.hurst = 0.7;
  p.seed = seed;
  p.octaves = 5;
  p.threads = 2;
  return p;
}

// A 5 x 5 periodic-compatible reference grid (last row and column repeat the first).
std::vector<float> reference_grid() {
  std::vector<float> r(25);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) r[size_t(j) * 5 + size_t(i)] = float(((i % 4) * 7 + (j % 4) * 3) % 5) - 2.0f;
  return r;
}

// 16 windows of odd sizes at odd offsets inside a w x h terrain, among them
// 1 x 1 samples, a full row, and windows at every edge and corner.
std::vector<terrain::Window> sixteen_windows(int64_t w, int64_t h) {
  std::vector<terrain::Window> out = {{0, 0, 1, 1},
                             {w - 1, h - 1, 1, 1},
                             {0, 0, 257, 131},
                             {w - 333, 0, 333, 95},
                             {0, h - 77, 411, 77},
                             {w - 129, h - 201, 129, 201},
                             {0, h / 4 + 1, int32_t(w), 3},
                             {w / 2 - 1, 0, 1, int32_t(h)}};
  uint64_t state = 12345;
  auto next = [&](uint64_t bound) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (state >> 33) % bound;
  };
  while (out.size() < 16) {
    const int32_t ww = int32_t(2 * next(300) + 1), wh = int32_t(2 * next(300) + 1);
    const int64_t x0 = int64_t(2 * next(uint64_t(w - ww) / 2) + 1), y0 = int64_t(2 * next(uint64_t(h - wh) / 2) + 1);
    out.push_back({x0, y0, ww, wh});
  }
  return out;
}

// Every one of the 16 windows equals the whole's samples bit for bit.
void expect_windows_equal_whole(const ft_terrain_params& p, const char* what) {
  const Heightfield whole = terrain::generate_terrain(p);
  for (const terrain::Window& win : sixteen_windows(whole.width(), whole.height())) {
    const Heightfield part = terrain::generate_terrain_window(p, 0, win.x0, win.y0, win.width, win.height);
    ASSERT_EQ(part.width(), win.width);
    ASSERT_EQ(part.height(), win.height);
    for (int32_t j = 0; j < win.height; ++j) {
      const float* a = part.data() + size_t(j) * size_t(win.width);
      const float* b = whole.data() + size_t(win.y0 + j) * size_t(whole.width()) + size_t(win.x0);
      ASSERT_EQ(std::memcmp(a, b, size_t(win.width) * sizeof(float)), 0)
          << what << ": window (" << win.x0 << ", " << win.y0 << ") " << win.width << " x " << win.height
          << " differs from the whole in its row " << j;
    }
  }
}

}  // namespace

TEST(TerrainWindow, MidpointWindowsEqualTheWholeBitForBit) {
  const std::vector<float> ref = reference_grid();
  for (int periodic : {0, 1}) {
    ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, 7);
    p.periodic = periodic;
    expect_windows_equal_whole(p, periodic ? "midpoint periodic" : "midpoint");
    p.reference = ref.data(), p.reference_size = 5;
    expect_windows_equal_whole(p, periodic ? "midpoint periodic reference" : "midpoint reference");
  }
}

TEST(TerrainWindow, AdditionsWindowsEqualTheWholeBitForBit) {
  const std::vector<float> ref = reference_grid();
  for (int periodic : {0, 1}) {
    ft_terrain_params p = params(FT_TERRAIN_ADDITIONS, 8);
    p.periodic = periodic;
    expect_windows_equal_whole(p, periodic ? "additions periodic" : "additions");
    p.reference = ref.data(), p.reference_size = 5;
    expect_windows_equal_whole(p, periodic ? "additions periodic reference" : "additions reference");
  }
}

TEST(TerrainWindow, FbmWindowsEqualTheWholeBitForBit) {
  for (int periodic : {0, 1}) {
    ft_terrain_params p = params(FT_TERRAIN_FBM, 9);
    p.periodic = periodic;
    p.warp = 0.5;  // the warp pass is per sample too
    expect_windows_equal_whole(p, periodic ? "fbm periodic" : "fbm");
  }
}

TEST(TerrainWindow, InterpolatedWindowsEqualTheWholeBitForBit) {
  for (int periodic : {0, 1}) {
    for (double lacunarity : {2.0, 2.7}) {
      ft_terrain_params p = params(FT_TERRAIN_INTERPOLATED, 10);
      p.periodic = periodic;
      p.lacunarity = lacunarity;
      expect_windows_equal_whole(p, periodic ? "interpolated periodic" : "interpolated");
    }
  }
}

TEST(TerrainWindow, MandelbrotWindowsEqualTheWholeBitForBit) {
  ft_terrain_params p = params(FT_TERRAIN_MANDELBROT, 1);
  p.width = p.height = 1025;
  p.iterations = 24;
  p.supersample = 1;
  expect_windows_equal_whole(p, "mandelbrot");
}

TEST(TerrainWindow, LevelOfDetailIsEveryOtherSampleOfTheWhole) {
  for (int method : {FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS}) {
    ft_terrain_params p = params(method, 11);
    p.levels = 9;
    const Heightfield whole = terrain::generate_terrain(p);
    for (int lod : {1, 3, 9}) {
      int64_t ew = 0, eh = 0;
      terrain::terrain_extent(p, lod, &ew, &eh);
      ASSERT_EQ(ew, (int64_t(1) << (9 - lod)) + 1);
      const int32_t w = int32_t(ew) - 1, h = int32_t(std::min<int64_t>(eh, 7));
      const Heightfield part = terrain::generate_terrain_window(p, lod, 1, 0, w, h);
      for (int32_t j = 0; j < h; ++j)
        for (int32_t i = 0; i < w; ++i)
          ASSERT_EQ(part.data()[size_t(j) * size_t(w) + size_t(i)],
                    whole.data()[size_t(j << lod) * size_t(whole.width()) + size_t((1 + i) << lod)])
              << "method " << method << " lod " << lod << " at " << i << ", " << j;
    }
  }
}

TEST(TerrainWindow, WindowsOfALevel24TerrainAgreeWhereTheyOverlap) {
  // 16,777,217^2 samples (1 PB as float32): never whole. Two overlapping
  // windows near its far corner must agree on their common samples, and a
  // coarse lod window must be the full window's every 2^lod-th sample.
  for (int periodic : {0, 1}) {
    ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, 5);
    p.levels = 24;
    p.periodic = periodic;
    const int64_t side = (int64_t(1) << 24) + 1;
    const Heightfield a = terrain::generate_terrain_window(p, 0, side - 300, side - 200, 300, 200);
    const Heightfield b = terrain::generate_terrain_window(p, 0, side - 150, side - 120, 150, 120);
    for (int j = 0; j < 120; ++j)
      for (int i = 0; i < 150; ++i) {
        const float va = a.data()[size_t(80 + j) * 300 + size_t(150 + i)];
        ASSERT_TRUE(std::isfinite(va));
        ASSERT_EQ(va, b.data()[size_t(j) * 150 + size_t(i)]) << i << ", " << j;
      }
    const Heightfield c = terrain::generate_terrain_window(p, 2, (side - 1) / 4 - 74, (side - 1) / 4 - 49, 75, 50);
    for (int j = 0; j < 50; ++j)
      for (int i = 0; i < 75; ++i)
        ASSERT_EQ(c.data()[size_t(j) * 75 + size_t(i)], a.data()[size_t(4 * j + 3) * 300 + size_t(4 * i + 3)]);
  }
}

TEST(TerrainWindow, BadWindowsAndSpectralAreRefusedWithAMessage) {
  auto message = [](const ft_terrain_params& p, int lod, int64_t x0, int64_t y0, int32_t w, int32_t h) {
    try {
      terrain::generate_terrain_window(p, lod, x0, y0, w, h);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, 1);
  EXPECT_NE(message(p, 0, 4000, 0, 98, 10).find("outside the terrain"), std::string::npos);
  EXPECT_NE(message(p, 0, -1, 0, 10, 10).find("outside the terrain"), std::string::npos);
  EXPECT_NE(message(p, 0, 0, 0, 0, 10).find("at least 1 x 1"), std::string::npos);
  EXPECT_NE(message(p, 13, 0, 0, 1, 1).find("lod"), std::string::npos);
  p.levels = 25;
  EXPECT_NE(message(p, 0, 0, 0, 1, 1).find("levels"), std::string::npos);
  p.levels = 24;
  EXPECT_NE(message(p, 0, 0, 0, 2000000000, 2000000000).find("window"), std::string::npos);
  p.method = FT_TERRAIN_SPECTRAL;
  EXPECT_NE(message(p, 0, 0, 0, 10, 10).find("global FFT"), std::string::npos);
  p.method = FT_TERRAIN_FBM;
  EXPECT_NE(message(p, 1, 0, 0, 10, 10).find("level of detail"), std::string::npos);
}
