// SPDX-License-Identifier: GPL-3.0-or-later
// The polyline C ABI as ctypes sees it: params init, generate into an
// ft_polylines handle, measure, and errors through ft_last_error().
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fracterra/fracterra.h"

namespace {

TEST(PolylineAbi, GeneratesAnFplAndMeasuresIt) {
  ft_polyline_params p;
  ASSERT_EQ(ft_polyline_params_init(&p), FT_OK);
  EXPECT_EQ(p.struct_size, sizeof(ft_polyline_params));
  EXPECT_EQ(p.method, FT_POLYLINE_FPL);
  p.spread = 0.2;
  p.depth = 10;
  const double base[] = {0, 0, 0, 2, 0, 0, 2, 2, 0};
  p.base = base;
  p.base_count = 3;
  ft_polylines* lines = nullptr;
  ASSERT_EQ(ft_polyline_generate(&p, &lines), FT_OK) << ft_last_error();
  ASSERT_NE(lines, nullptr);
  EXPECT_EQ(ft_polylines_line_count(lines), 1);
  EXPECT_EQ(ft_polylines_vertex_count(lines), 2 * 1024 + 1);
  const double* xyz = ft_polylines_xyz(lines);
  EXPECT_EQ(xyz[3 * 1024 + 0], 2.0);  // the middle node survives
  EXPECT_EQ(xyz[3 * 1024 + 1], 0.0);
  ft_polyline_stats s;
  s.struct_size = sizeof s;
  ASSERT_EQ(ft_polyline_measure(lines, &s), FT_OK) << ft_last_error();
  EXPECT_EQ(s.vertex_count, 2049);
  EXPECT_GT(s.gamma, 1.0);
  EXPECT_GT(s.box_dimension, 1.0);
  EXPECT_LT(s.box_dimension, 1.3);
  EXPECT_GT(s.box_sizes, 3);
  EXPECT_GT(s.mass_dimension, 1.0);
  ft_polylines_free(lines);
  ft_polylines_free(nullptr);
}

TEST(PolylineAbi, KochMeasuresNearLog4OverLog3) {
  ft_polyline_params p;
  ft_polyline_params_init(&p);
  p.method = FT_POLYLINE_KOCH;
  p.depth = 7;
  ft_polylines* lines = nullptr;
  ASSERT_EQ(ft_polyline_generate(&p, &lines), FT_OK) << ft_last_error();
  ft_polyline_stats s;
  s.struct_size = sizeof s;
  ASSERT_EQ(ft_polyline_measure(lines, &s), FT_OK);
  EXPECT_NEAR(s.box_dimension, std::log(4.0) / std::log(3.0), 0.03);
  ft_polylines_free(lines);
}

TEST(PolylineAbi, BadInputReturnsStatusAndMessage) {
  ft_polyline_params p;
  ft_polyline_params_init(&p);
  const double base[] = {0, 0, 0, 0, 0, 0};
  p.base = base;
  p.base_count = 2;
  ft_polylines* lines = reinterpret_cast<ft_polylines*>(1);
  EXPECT_EQ(ft_polyline_generate(&p, &lines), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(lines, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("coincides"), std::string::npos) << ft_last_error();
  EXPECT_EQ(ft_polyline_generate(nullptr, &lines), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_polyline_params_init(nullptr), FT_ERR_INVALID_ARGUMENT);
  ft_polyline_stats s;
  s.struct_size = 4;
  EXPECT_EQ(ft_polyline_measure(nullptr, &s), FT_ERR_INVALID_ARGUMENT);
  ft_polyline_params_init(&p);
  ASSERT_EQ(ft_polyline_generate(&p, &lines), FT_OK);
  EXPECT_EQ(ft_polyline_measure(lines, &s), FT_ERR_INVALID_ARGUMENT);  // struct_size too small
  ft_polylines_free(lines);
}

TEST(PolylineAbi, CancelsThroughTheProgressCallback) {
  ft_polyline_params p;
  ft_polyline_params_init(&p);
  p.depth = 16;
  p.progress = [](void*, double) -> int32_t { return 1; };
  ft_polylines* lines = nullptr;
  EXPECT_EQ(ft_polyline_generate(&p, &lines), FT_ERR_CANCELLED);
  EXPECT_EQ(lines, nullptr);
}

}  // namespace
