// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI as ctypes sees it: statuses, ft_last_error, handles, defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"

namespace {

TEST(CApi, VersionMatchesTheHeader) {
  EXPECT_EQ(ft_abi_version(), uint32_t(FT_ABI_VERSION));
  EXPECT_STREQ(ft_version_string(), FT_PROJECT_VERSION);  // the CMake project version
}

TEST(CApi, GeneratesATerrainIntoALibraryOwnedHandle) {
  ft_terrain_params p;
  ASSERT_EQ(ft_terrain_params_init(&p), FT_OK);
  EXPECT_EQ(p.struct_size, sizeof(ft_terrain_params));
  p.levels = 5;
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  EXPECT_STREQ(ft_last_error(), "");
  ASSERT_EQ(ft_heightfield_width(hf), 33);
  ASSERT_EQ(ft_heightfield_height(hf), 33);
  std::vector<float> copy(33 * 33);
  ASSERT_EQ(ft_heightfield_copy(hf, copy.data(), copy.size()), FT_OK);
  EXPECT_EQ(std::memcmp(copy.data(), ft_heightfield_data(hf), copy.size() * sizeof(float)), 0);
  double lo, hi;
  ASSERT_EQ(ft_heightfield_stats(hf, &lo, &hi, nullptr, nullptr), FT_OK);
  EXPECT_LT(lo, hi);
  EXPECT_EQ(ft_heightfield_copy(hf, copy.data(), 10), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_heightfield_world_size(hf), 10.0);
  EXPECT_EQ(ft_heightfield_set_world_size(hf, -1.0), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("world_size"), std::string::npos) << ft_last_error();
  EXPECT_EQ(ft_heightfield_set_world_size(hf, 250.0), FT_OK);
  EXPECT_EQ(ft_heightfield_world_size(hf), 250.0);
  ft_heightfield_free(hf);
  ft_heightfield_free(nullptr);  // harmless
}

TEST(CApi, BadParametersReturnAStatusAndAMessageAndNoHandle) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.hurst = NAN;
  ft_heightfield* hf = reinterpret_cast<ft_heightfield*>(0x1);
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(hf, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("hurst"), std::string::npos) << ft_last_error();
  EXPECT_STREQ(ft_status_name(FT_ERR_INVALID_ARGUMENT), "FT_ERR_INVALID_ARGUMENT");
  EXPECT_EQ(ft_terrain_generate(nullptr, &hf), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_terrain_generate(&p, nullptr), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_terrain_params_init(nullptr), FT_ERR_INVALID_ARGUMENT);
}

TEST(CApi, ABindingBuiltForAbi10StillWorks) {
  // ABI 1.1 appended world_size; a 1.0 caller's smaller struct is accepted
  // and the missing field takes its default.
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.levels = 4;
  p.world_size = -1;  // beyond the 1.0 struct: must not be read
  p.struct_size = offsetof(ft_terrain_params, world_size);
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  EXPECT_EQ(ft_heightfield_world_size(hf), 10.0);
  ft_heightfield_free(hf);
  p.struct_size = sizeof(ft_terrain_params) + 8;  // a newer caller than this library
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("struct_size"), std::string::npos) << ft_last_error();
}

TEST(CApi, MemoryCapRefusesBeforeAllocating) {
  ft_set_memory_cap(1 << 20);
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.levels = 10;  // 1025^2 floats = 4.2 MB
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_TOO_LARGE);
  EXPECT_NE(std::string(ft_last_error()).find("memory cap"), std::string::npos) << ft_last_error();
  EXPECT_NE(std::string(ft_last_error()).find("needs 4.01 MiB"), std::string::npos) << ft_last_error();
  ft_set_memory_cap(0);
  EXPECT_EQ(ft_memory_cap(), uint64_t(8) << 30);
}

TEST(CApi, CancelledCallReturnsCancelledAndNoHandle) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.levels = 8;
  p.progress = [](void*, double f) -> int32_t { return f >= 0.25; };
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_CANCELLED);
  EXPECT_EQ(hf, nullptr);
}

TEST(CApi, ProfileFillsACallerBuffer) {
  ft_profile_params p;
  ASSERT_EQ(ft_profile_params_init(&p), FT_OK);
  p.levels = 6;
  ASSERT_EQ(ft_profile_length(6), 65);
  std::vector<float> x(65);
  ASSERT_EQ(ft_profile_generate(&p, x.data(), x.size()), FT_OK) << ft_last_error();
  EXPECT_EQ(x[0], 0.0f);
  EXPECT_EQ(ft_profile_generate(&p, x.data(), 64), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("needs 65"), std::string::npos) << ft_last_error();
}

TEST(CApi, PolylineHandlesRoundTrip) {
  const double xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 5, 5, 5};
  const double radii[] = {1, 2, 3, 4};
  const int64_t offsets[] = {0, 3, 4};
  ft_polylines* p = nullptr;
  ASSERT_EQ(ft_polylines_create(xyz, radii, 4, offsets, 2, &p), FT_OK) << ft_last_error();
  EXPECT_EQ(ft_polylines_line_count(p), 2);
  EXPECT_EQ(ft_polylines_vertex_count(p), 4);
  EXPECT_EQ(ft_polylines_xyz(p)[9], 5.0);
  EXPECT_EQ(ft_polylines_radii(p)[2], 3.0);
  EXPECT_EQ(ft_polylines_offsets(p)[1], 3);
  ft_polylines_free(p);
  const int64_t bad[] = {0, 5, 4};
  EXPECT_EQ(ft_polylines_create(xyz, radii, 4, bad, 2, &p), FT_ERR_INVALID_ARGUMENT);
}

TEST(CApi, MandelbrotTerrainAndItsLevelCurves) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  EXPECT_EQ(p.center_x, -0.5);
  EXPECT_EQ(p.center_y, 0.0);
  EXPECT_EQ(p.zoom, 1.0);
  EXPECT_EQ(p.iterations, 64);
  EXPECT_EQ(p.supersample, 2);
  p.method = FT_TERRAIN_MANDELBROT;
  p.width = 129, p.height = 97;
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  // c = 0 is sample ((0 - -0.5) / step + 64, 48) with step 4 / 128: inside,
  // the plateau at the height of escape time 64, above the corner -2.5 + 1.5i.
  double top = 0;
  ASSERT_EQ(ft_mandelbrot_level_height(&p, 64.0, &top), FT_OK);
  EXPECT_EQ(ft_heightfield_data(hf)[48 * 129 + 80], float(top));
  EXPECT_LT(ft_heightfield_data(hf)[0], float(top));
  double h3 = 0, h6 = 0;
  ASSERT_EQ(ft_mandelbrot_level_height(&p, 5.0, &h3), FT_OK);
  ASSERT_EQ(ft_mandelbrot_level_height(&p, 8.0, &h6), FT_OK);
  EXPECT_LT(h3, h6);
  double bad = 1;
  EXPECT_EQ(ft_mandelbrot_level_height(&p, NAN, &bad), FT_ERR_INVALID_ARGUMENT);
  const double levels[] = {h3, h6};
  ft_polylines* curves = nullptr;
  ASSERT_EQ(ft_level_curves(hf, levels, 2, &curves), FT_OK) << ft_last_error();
  EXPECT_GE(ft_polylines_line_count(curves), 2);
  ft_polylines_free(curves);
  EXPECT_EQ(ft_level_curves(hf, levels, 0, &curves), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(curves, nullptr);
  const double nan_level[] = {NAN};
  EXPECT_EQ(ft_level_curves(hf, nan_level, 1, &curves), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("levels[0]"), std::string::npos) << ft_last_error();
  ft_heightfield_free(hf);
}

TEST(CApi, MandelbrotBadInputGetsAStatusAndAMessage) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.method = FT_TERRAIN_MANDELBROT;
  const struct {
    const char* field;
    void (*spoil)(ft_terrain_params&);
    const char* message;
  } cases[] = {
      {"zoom 0", [](ft_terrain_params& q) { q.zoom = 0; }, "zoom must be"},
      {"zoom -1", [](ft_terrain_params& q) { q.zoom = -1; }, "zoom must be"},
      {"NaN centre", [](ft_terrain_params& q) { q.center_y = NAN; }, "center_y must be in [-4, 4], got NaN"},
      {"iterations 0", [](ft_terrain_params& q) { q.iterations = 0; }, "iterations must be in 1..16777216"},
      {"iterations 2^24 + 1", [](ft_terrain_params& q) { q.iterations = (1 << 24) + 1; }, "iterations"},
      {"zoom 1e13", [](ft_terrain_params& q) { q.zoom = 1e13; }, "beyond double precision"},
  };
  for (const auto& c : cases) {
    ft_terrain_params q = p;
    c.spoil(q);
    ft_heightfield* hf = reinterpret_cast<ft_heightfield*>(0x1);
    EXPECT_EQ(ft_terrain_generate(&q, &hf), FT_ERR_INVALID_ARGUMENT) << c.field;
    EXPECT_EQ(hf, nullptr);
    EXPECT_NE(std::string(ft_last_error()).find(c.message), std::string::npos) << c.field << ": " << ft_last_error();
  }
}

TEST(CApi, ABindingBuiltForAbi11GetsTheMandelbrotDefaults) {
  // ABI 1.2 appended the Mandelbrot fields; a 1.1 caller's struct ends at
  // world_size and the Mandelbrot view takes its defaults.
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.method = FT_TERRAIN_MANDELBROT;
  p.width = p.height = 33;
  p.zoom = -1;  // beyond the 1.1 struct: must not be read
  p.struct_size = offsetof(ft_terrain_params, center_x);
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
  ft_heightfield_free(hf);
}

}  // namespace

TEST(CApi, AWindowThroughTheAbiEqualsTheWholesSamples) {
  ft_terrain_params p;
  ASSERT_EQ(ft_terrain_params_init(&p), FT_OK);
  p.levels = 8;
  int64_t w = 0, h = 0;
  ASSERT_EQ(ft_terrain_extent(&p, 0, &w, &h), FT_OK);
  EXPECT_EQ(w, 257);
  ASSERT_EQ(ft_terrain_extent(&p, 2, &w, &h), FT_OK);
  EXPECT_EQ(h, 65);
  ft_heightfield* whole = nullptr;
  ft_heightfield* part = nullptr;
  ASSERT_EQ(ft_terrain_generate(&p, &whole), FT_OK);
  ASSERT_EQ(ft_terrain_generate_window(&p, 31, 17, 45, 23, &part), FT_OK);
  std::vector<float> a(257 * 257), b(45 * 23);
  ASSERT_EQ(ft_heightfield_copy(whole, a.data(), a.size()), FT_OK);
  ASSERT_EQ(ft_heightfield_copy(part, b.data(), b.size()), FT_OK);
  for (int j = 0; j < 23; ++j)
    ASSERT_EQ(std::memcmp(&b[size_t(j) * 45], &a[size_t(17 + j) * 257 + 31], 45 * sizeof(float)), 0) << j;
  ft_heightfield_free(part);
  ft_heightfield_free(whole);
  // Outside, spectral and NULL outputs are statuses with a message, no handle.
  part = reinterpret_cast<ft_heightfield*>(&p);
  EXPECT_EQ(ft_terrain_generate_window(&p, 250, 0, 8, 8, &part), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(part, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("outside the terrain"), std::string::npos);
  p.method = FT_TERRAIN_SPECTRAL;
  EXPECT_EQ(ft_terrain_generate_window(&p, 0, 0, 8, 8, &part), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("global FFT"), std::string::npos);
  EXPECT_NE(ft_terrain_extent(&p, 0, nullptr, &h), FT_OK);
}
