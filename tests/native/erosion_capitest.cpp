// SPDX-License-Identifier: GPL-3.0-or-later
// The erosion C ABI as ctypes sees it: defaults, presets, the maps, bad
// input as a status with a message, cancel, and nothing leaked on failure.
#include <gtest/gtest.h>

#include <cstddef>

#include <cmath>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"

namespace {

ft_heightfield* terrain(int32_t size) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.method = FT_TERRAIN_FBM;
  p.width = p.height = size;
  ft_heightfield* hf = nullptr;
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_OK);
  return hf;
}

TEST(ErosionCapi, PresetErodesAndReturnsEveryMap) {
  ft_heightfield* hf = terrain(65);
  ft_erosion_params p;
  ASSERT_EQ(ft_erosion_params_init(&p), FT_OK);
  EXPECT_EQ(p.fluvial_steps + p.hydraulic_iterations + p.thermal_iterations, 0) << "init: every process off";
  EXPECT_EQ(p.duration, 0.0) << "init: no run";
  ASSERT_EQ(ft_erosion_preset("land", &p), FT_OK);
  EXPECT_GT(p.duration, 0);
  ft_heightfield* out = nullptr;
  ft_heightfield* maps[FT_MAP_COUNT];
  ASSERT_EQ(ft_erode(hf, &p, &out, maps), FT_OK) << ft_last_error();
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(ft_heightfield_width(out), 65);
  for (auto* m : maps) {
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(ft_heightfield_width(m), 65);
  }
  double mn, mx, mean, sd;
  ASSERT_EQ(ft_heightfield_stats(maps[FT_MAP_DRAINAGE_AREA], &mn, &mx, &mean, &sd), FT_OK);
  const double spacing = ft_heightfield_world_size(hf) / 64;
  EXPECT_GT(mx, 64.0 * spacing * spacing) << "areas in world units^2: a channel drains many cells";
  EXPECT_LE(mx, 65.0 * 65.0 * spacing * spacing * 1.0001);
  ft_drainage_stats st;
  EXPECT_EQ(ft_drainage_statistics(out, 0, 10, &st), FT_OK) << ft_last_error();
  EXPECT_GT(st.hack_bins, 2);
  for (auto* m : maps) ft_heightfield_free(m);
  ft_heightfield_free(out);
  ft_heightfield_free(hf);
}

TEST(ErosionCapi, BadInputIsAStatusWithTheParameterNamed) {
  ft_heightfield* hf = terrain(33);
  ft_erosion_params p;
  ft_erosion_params_init(&p);
  p.rain = NAN;
  p.hydraulic_iterations = 3;
  ft_heightfield* out = reinterpret_cast<ft_heightfield*>(1);
  ft_heightfield* maps[FT_MAP_COUNT];
  EXPECT_EQ(ft_erode(hf, &p, &out, maps), FT_ERR_INVALID_ARGUMENT);
  // Checked by the table (params.h) at the C boundary: the C field's name.
  EXPECT_NE(std::string(ft_last_error()).find("rain"), std::string::npos) << ft_last_error();
  EXPECT_EQ(out, nullptr);
  for (auto* m : maps) EXPECT_EQ(m, nullptr);
  ft_erosion_params_init(&p);
  p.struct_size = 8;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_erosion_preset("volcano", &p), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("valleys"), std::string::npos);
  EXPECT_EQ(ft_erode(nullptr, &p, &out, nullptr), FT_ERR_INVALID_ARGUMENT);
  ft_heightfield_free(hf);
}

// Issue 25's input: zeros with one sample at +1e38 and one at -1e38. The
// fluvial solve overflowed (inf - inf = NaN) and its routing never ended;
// now the library refuses it, naming the sample and the limit, and takes
// the same terrain scaled into the limit.
TEST(ErosionCapi, HeightsBeyondTheFloatLimitAreRefusedNamingIt) {
  for (const float big : {1e38f, 2e15f, 1e15f}) {
    std::vector<float> z(65 * 65, 0.0f);
    z[20 * 65 + 20] = big;
    z[40 * 65 + 40] = -big;
    ft_heightfield* hf = nullptr;
    ASSERT_EQ(ft_heightfield_create(65, 65, z.data(), &hf), FT_OK) << ft_last_error();
    ft_erosion_params p;
    ft_erosion_params_init(&p);
    p.fluvial_steps = 60;
    ft_heightfield* out = reinterpret_cast<ft_heightfield*>(1);
    const ft_status s = ft_erode(hf, &p, &out, nullptr);
    if (big > 1e15f) {
      EXPECT_EQ(s, FT_ERR_INVALID_ARGUMENT) << big;
      const std::string m = ft_last_error();
      EXPECT_NE(m.find("sample 20, 20"), std::string::npos) << m;
      EXPECT_NE(m.find("within +-1e+15 world units"), std::string::npos) << m;
      EXPECT_EQ(out, nullptr);
    } else {
      ASSERT_EQ(s, FT_OK) << ft_last_error();
      double mn, mx, mean, sd;
      ASSERT_EQ(ft_heightfield_stats(out, &mn, &mx, &mean, &sd), FT_OK);
      // Within the input's range, to float rounding (an ulp at 1e15 is 1.3e8).
      EXPECT_TRUE(std::isfinite(mn) && std::isfinite(mx) && mn >= -1.001e15 && mx <= 1.001e15) << mn << " " << mx;
      ft_heightfield_free(out);
    }
    ft_heightfield_free(hf);
  }
}

TEST(ErosionCapi, TheFittedPresetAndItsUpliftFlagAreValidated) {
  ft_heightfield* hf = terrain(33);
  ft_erosion_params p;
  ASSERT_EQ(ft_erosion_preset_fitted("valleys", hf, &p), FT_OK) << ft_last_error();
  EXPECT_EQ(p.uplift, 0.0) << "ABI 2.14: presets are in world units and years, nothing is fitted";
  EXPECT_EQ(p.uplift_follows_terrain, 0);
  EXPECT_GT(p.duration, 0.0);
  EXPECT_EQ(ft_erosion_preset_fitted("volcano", hf, &p), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("valleys"), std::string::npos) << ft_last_error();
  EXPECT_EQ(ft_erosion_preset_fitted("valleys", nullptr, &p), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("terrain"), std::string::npos) << ft_last_error();
  EXPECT_EQ(ft_erosion_preset_fitted(nullptr, hf, &p), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_erosion_preset_fitted("valleys", hf, nullptr), FT_ERR_INVALID_ARGUMENT);
  // A caller from before the flag (ABI 2.11's size) is accepted and gets it
  // off (the flag is a C boolean: any non-zero value is on).
  ft_heightfield* out = nullptr;
  ft_erosion_params_init(&p);
  p.struct_size = uint32_t(offsetof(ft_erosion_params, uplift_follows_terrain));
  p.uplift_follows_terrain = 2;  // beyond the caller's struct: never read
  p.fluvial_steps = 1;
  p.uplift = 1e-5;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_OK) << ft_last_error();
  ft_heightfield_free(out);
  // A caller from ABI 2.12 (before the maps) gets no mask, whatever lies beyond its struct.
  ft_erosion_preset("badlands", &p);
  p.struct_size = uint32_t(offsetof(ft_erosion_params, strength));
  p.strength = 7;
  p.erosion_mask = reinterpret_cast<const float*>(1);
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_OK) << ft_last_error();
  ft_heightfield_free(out);
  ft_heightfield_free(hf);
}

TEST(ErosionCapi, MapsOfTheWrongSizeOrWithNaNAreRefused) {
  ft_heightfield* hf = terrain(33);
  ft_erosion_params p;
  ft_erosion_preset("badlands", &p);
  const float mask[] = {1, 0.5f, NAN, 1};
  p.erosion_mask = mask;
  p.erosion_mask_width = 2;
  p.erosion_mask_height = 2;
  ft_heightfield* out = nullptr;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("erosion_mask's values must be in [0, 1]; sample 0, 1"),
            std::string::npos) << ft_last_error();
  p.erosion_mask = nullptr;
  p.rain_map = mask;
  p.rain_map_width = 70000;
  p.rain_map_height = 1;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("rain_map_width must be in 2..65536"), std::string::npos)
      << ft_last_error();
  p.rain_map = nullptr;
  p.rain_map_width = p.rain_map_height = 0;
  p.strength = 1.5;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("strength must be in [0, 1], got 1.5"), std::string::npos)
      << ft_last_error();
  ft_heightfield_free(hf);
}

// ABI 2.21's sea and the rain passes' limits: each bad value is refused at
// the C boundary with the field and its range named.
TEST(ErosionCapi, BadSeaAndRainPassValuesAreRefusedWithTheirRange) {
  ft_heightfield* hf = terrain(33);
  struct Case {
    void (*set)(ft_erosion_params&);
    const char* words;
  };
  const Case cases[] = {
      {[](ft_erosion_params& p) { p.sea = 3; }, "sea must be one of"},
      {[](ft_erosion_params& p) { p.sea_fraction = 1.0; }, "sea_fraction must be"},
      {[](ft_erosion_params& p) { p.sea_level = 1e16; }, "sea_level must be"},
      {[](ft_erosion_params& p) { p.sea_level = NAN; }, "sea_level must be"},
      {[](ft_erosion_params& p) { p.capacity = 1e7; }, "capacity must be"},
      {[](ft_erosion_params& p) { p.rain = 1e7; }, "rain must be"},
  };
  for (const Case& c : cases) {
    ft_erosion_params p;
    ft_erosion_params_init(&p);
    c.set(p);
    ft_heightfield* out = nullptr;
    EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_ERR_INVALID_ARGUMENT) << c.words;
    EXPECT_NE(std::string(ft_last_error()).find(c.words), std::string::npos) << ft_last_error();
    EXPECT_EQ(out, nullptr);
  }
  ft_erosion_params p;  // the limits themselves are accepted
  ft_erosion_params_init(&p);
  p.sea = FT_WATER_SEA_FRACTION;
  p.sea_fraction = 0.3;
  p.capacity = 1e6;
  ft_heightfield* out = nullptr;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_OK) << ft_last_error();
  ft_heightfield_free(out);
  ft_heightfield_free(hf);
}

TEST(ErosionCapi, CancelFromTheProgressCallback) {
  ft_heightfield* hf = terrain(65);
  ft_erosion_params p;
  ft_erosion_preset("rain", &p);
  p.progress = [](void*, double f) -> int32_t { return f > 0.3 ? 1 : 0; };
  ft_heightfield* out = nullptr;
  EXPECT_EQ(ft_erode(hf, &p, &out, nullptr), FT_ERR_CANCELLED);
  EXPECT_EQ(out, nullptr);
  ft_heightfield_free(hf);
}

}  // namespace
