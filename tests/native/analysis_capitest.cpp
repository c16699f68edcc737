// SPDX-License-Identifier: GPL-3.0-or-later
// The analysis C ABI as ctypes sees it: status codes, messages, NULL
// handling, ownership.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>
#include <unistd.h>

#include "fracterra/fracterra.h"

namespace {

ft_heightfield* make_terrain(int levels, double hurst, uint64_t seed) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.levels = levels, p.hurst = hurst, p.seed = seed;
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  return hf;
}

TEST(AnalysisCapi, HurstOfAHeightfieldAndAProfile) {
  ft_heightfield* hf = make_terrain(9, 0.6, 3);
  ft_hurst_params p;
  ASSERT_EQ(ft_hurst_params_init(&p), FT_OK);
  EXPECT_EQ(p.method, FT_HURST_VARIOGRAM_ALIGNED);
  ft_hurst_result r;
  r.struct_size = sizeof r;
  ASSERT_EQ(ft_hurst_heightfield(hf, &p, &r), FT_OK) << ft_last_error();
  EXPECT_NEAR(r.hurst, 0.6, 0.08);
  EXPECT_DOUBLE_EQ(r.dimension, 3 - r.hurst);
  EXPECT_EQ(r.band_lo, 1);
  EXPECT_EQ(r.band_hi, 32);
  EXPECT_EQ(r.band_is_frequency, 0);
  EXPECT_EQ(r.points, 6);
  p.method = FT_HURST_SPECTRAL;
  p.transects = 1;
  ASSERT_EQ(ft_hurst_heightfield(hf, &p, &r), FT_OK) << ft_last_error();
  EXPECT_EQ(r.band_is_frequency, 1);
  EXPECT_EQ(r.transects, 1);
  // A row of the terrain as a profile, default parameters (params NULL).
  ASSERT_EQ(ft_hurst_profile(ft_heightfield_data(hf), 513, nullptr, &r), FT_OK) << ft_last_error();
  EXPECT_DOUBLE_EQ(r.dimension, 2 - r.hurst);
  ft_heightfield_free(hf);
}

TEST(AnalysisCapi, HurstRefusesBadArgumentsWithAMessage) {
  ft_hurst_result r;
  r.struct_size = sizeof r;
  float v[4] = {1, 2, 3, 4};
  EXPECT_EQ(ft_hurst_profile(v, 4, nullptr, &r), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("at least 8"), std::string::npos) << ft_last_error();
  EXPECT_EQ(ft_hurst_profile(nullptr, 100, nullptr, &r), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_hurst_heightfield(nullptr, nullptr, &r), FT_ERR_INVALID_ARGUMENT);
  ft_hurst_params p;
  ft_hurst_params_init(&p);
  p.method = 9;
  std::vector<float> w(64);
  for (size_t i = 0; i < w.size(); ++i) w[i] = float(std::sin(0.3 * double(i)) + 0.01 * double(i * i));
  EXPECT_EQ(ft_hurst_profile(w.data(), w.size(), &p, &r), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("method"), std::string::npos);
  ft_hurst_params_init(&p);
  p.struct_size = 4;
  EXPECT_EQ(ft_hurst_profile(w.data(), w.size(), &p, &r), FT_ERR_INVALID_ARGUMENT);
  ft_hurst_params_init(&p);
  p.lag_min = NAN;
  EXPECT_EQ(ft_hurst_profile(w.data(), w.size(), &p, &r), FT_ERR_INVALID_ARGUMENT);
}

ft_heightfield* make_fbm(int width, int height) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.method = FT_TERRAIN_FBM, p.width = width, p.height = height, p.seed = 4;
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  return hf;
}

// FT_HURST_AUTO: the recommendation `fracterra analyze` reports, so the CLI
// and Blender's measure operator show one H for one terrain.
TEST(AnalysisCapi, HurstAutoChoosesByTheGridAndSaysWhy) {
  struct Case {
    ft_heightfield* hf;
    int32_t method, reason;
  };
  for (const Case& c : {Case{make_terrain(8, 0.6, 3), FT_HURST_VARIOGRAM_ALIGNED, FT_HURST_REASON_DYADIC_GRID},
                        Case{make_fbm(300, 260), FT_HURST_SPECTRAL, FT_HURST_REASON_LONG_RECORD},
                        Case{make_fbm(100, 90), FT_HURST_VARIOGRAM, FT_HURST_REASON_SHORT_RECORD}}) {
    ft_hurst_params p;
    ft_hurst_params_init(&p);
    p.method = FT_HURST_AUTO;
    ft_hurst_result a, named;
    a.struct_size = named.struct_size = sizeof a;
    ASSERT_EQ(ft_hurst_heightfield(c.hf, &p, &a), FT_OK) << ft_last_error();
    EXPECT_EQ(a.method, c.method);
    EXPECT_EQ(a.auto_reason, c.reason);
    ASSERT_NE(a.auto_reason_text, nullptr);
    EXPECT_GT(std::strlen(a.auto_reason_text), 20u);
    p.method = c.method;
    ASSERT_EQ(ft_hurst_heightfield(c.hf, &p, &named), FT_OK) << ft_last_error();
    EXPECT_EQ(a.hurst, named.hurst);
    ft_heightfield_free(c.hf);
  }
  // A profile: the same rule along its length.
  std::vector<float> w(300);
  for (size_t i = 0; i < w.size(); ++i) w[i] = float(std::sin(0.3 * double(i)) + 0.01 * double(i));
  ft_hurst_params p;
  ft_hurst_params_init(&p);
  p.method = FT_HURST_AUTO;
  ft_hurst_result r;
  r.struct_size = sizeof r;
  ASSERT_EQ(ft_hurst_profile(w.data(), w.size(), &p, &r), FT_OK) << ft_last_error();
  EXPECT_EQ(r.method, FT_HURST_SPECTRAL);
  ASSERT_EQ(ft_hurst_profile(w.data(), 257, &p, &r), FT_OK) << ft_last_error();
  EXPECT_EQ(r.method, FT_HURST_VARIOGRAM_ALIGNED);
}

// A caller built before ABI 1.2 has a result struct that ends after
// `points`: a named method never writes past it.
TEST(AnalysisCapi, AResultIsWrittenUpToTheCallersStructSize) {
  ft_heightfield* hf = make_terrain(6, 0.6, 3);
  // A caller of a later ABI with a longer struct: this library writes its own fields only.
  struct Longer {
    ft_hurst_result r;
    unsigned char later[16];
  } big;
  std::memset(&big, 0xAB, sizeof big);
  big.r.struct_size = sizeof big;
  ASSERT_EQ(ft_hurst_heightfield(hf, nullptr, &big.r), FT_OK) << ft_last_error();
  for (unsigned char c : big.later) EXPECT_EQ(c, 0xAB);
  EXPECT_EQ(big.r.struct_size, sizeof big);
  EXPECT_EQ(big.r.points, 3);  // lags 1, 2, 4: the result was written
  EXPECT_EQ(big.r.auto_reason, FT_HURST_REASON_NONE);  // a named method
  EXPECT_STREQ(big.r.auto_reason_text, "");
  // A size no 2.x struct ever had is refused, and nothing is written.
  ft_hurst_result r;
  std::memset(&r, 0xAB, sizeof r);
  r.struct_size = offsetof(ft_hurst_result, auto_reason);
  EXPECT_EQ(ft_hurst_heightfield(hf, nullptr, &r), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("ft_hurst_result.struct_size"), std::string::npos) << ft_last_error();
  EXPECT_EQ(r.points, int32_t(0xABABABAB));
  ft_heightfield_free(hf);
}

TEST(AnalysisCapi, CoastlineIsAPolylineHandle) {
  ft_heightfield* hf = make_terrain(7, 0.5, 2);
  ft_polylines* lines = reinterpret_cast<ft_polylines*>(1);
  ASSERT_EQ(ft_coastline(hf, 0.5, 1, &lines), FT_OK) << ft_last_error();
  ASSERT_NE(lines, nullptr);
  EXPECT_GT(ft_polylines_line_count(lines), 0);
  const double* xyz = ft_polylines_xyz(lines);
  EXPECT_GE(xyz[0], 0);
  EXPECT_LE(xyz[0], 128);
  ft_polylines_free(lines);
  double lo, hi;
  ft_heightfield_stats(hf, &lo, &hi, nullptr, nullptr);
  ASSERT_EQ(ft_coastline(hf, hi + 1, 0, &lines), FT_OK);  // above the data: empty, not an error
  EXPECT_EQ(ft_polylines_line_count(lines), 0);
  ft_polylines_free(lines);
  EXPECT_EQ(ft_coastline(hf, 1.5, 1, &lines), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(lines, nullptr);
  EXPECT_EQ(ft_coastline(nullptr, 0, 0, &lines), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_coastline(hf, 0, 0, nullptr), FT_ERR_INVALID_ARGUMENT);
  ft_heightfield_free(hf);
}

TEST(AnalysisCapi, CloudsFillABufferOrWriteAPng) {
  ft_heightfield* hf = make_terrain(6, 0.8, 1);
  ft_clouds_params p;
  ASSERT_EQ(ft_clouds_params_init(&p), FT_OK);
  std::vector<uint16_t> px(65 * 65);
  ASSERT_EQ(ft_clouds(hf, &p, px.data(), px.size()), FT_OK) << ft_last_error();
  EXPECT_EQ(*std::max_element(px.begin(), px.end()), 255);
  EXPECT_EQ(ft_clouds(hf, &p, px.data(), px.size() - 1), FT_ERR_INVALID_ARGUMENT);
  p.bit_depth = 16;
  ASSERT_EQ(ft_clouds(hf, &p, px.data(), px.size()), FT_OK);
  EXPECT_EQ(*std::max_element(px.begin(), px.end()), 65535);
  const auto path = std::filesystem::temp_directory_path() / ("ft_capi_clouds_" + std::to_string(::getpid()) + ".png");
  ASSERT_EQ(ft_clouds_write_png(hf, &p, path.string().c_str()), FT_OK) << ft_last_error();
  EXPECT_TRUE(std::filesystem::exists(path));
  std::filesystem::remove(path);
  EXPECT_EQ(ft_clouds_write_png(hf, &p, "/nonexistent-dir/c.png"), FT_ERR_IO);
  p.bit_depth = 4;
  EXPECT_EQ(ft_clouds(hf, &p, px.data(), px.size()), FT_ERR_INVALID_ARGUMENT);
  ft_heightfield_free(hf);
}

}  // namespace
