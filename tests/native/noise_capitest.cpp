// SPDX-License-Identifier: GPL-3.0-or-later
// fbm, spectral and interpolated terrains through the shared library's C
// ABI, as ctypes calls them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fracterra/fracterra.h"

namespace {

TEST(NoiseCapi, GeneratesEveryNewMethodAtAnySize) {
  for (int method : {FT_TERRAIN_FBM, FT_TERRAIN_SPECTRAL, FT_TERRAIN_INTERPOLATED}) {
    ft_terrain_params p;
    ASSERT_EQ(ft_terrain_params_init(&p), FT_OK);
    p.method = method;
    p.width = 70;
    p.height = 33;
    ft_heightfield* hf = nullptr;
    ASSERT_EQ(ft_terrain_generate(&p, &hf), FT_OK) << ft_last_error();
    EXPECT_EQ(ft_heightfield_width(hf), 70);
    EXPECT_EQ(ft_heightfield_height(hf), 33);
    double mn = 0, mx = 0, mean = 0, sd = 0;
    ASSERT_EQ(ft_heightfield_stats(hf, &mn, &mx, &mean, &sd), FT_OK);
    EXPECT_TRUE(std::isfinite(mn) && std::isfinite(mx) && sd > 0);
    ft_heightfield_free(hf);
  }
}

TEST(NoiseCapi, RejectsNanLacunarityWithAMessage) {
  ft_terrain_params p;
  ft_terrain_params_init(&p);
  p.method = FT_TERRAIN_FBM;
  p.lacunarity = std::nan("");
  ft_heightfield* hf = reinterpret_cast<ft_heightfield*>(&p);  // must be reset to NULL
  EXPECT_EQ(ft_terrain_generate(&p, &hf), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(hf, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("lacunarity"), std::string::npos) << ft_last_error();
}

}  // namespace
