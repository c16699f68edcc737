// SPDX-License-Identifier: GPL-3.0-or-later
// The terrain entry point: validates ft_terrain_params and dispatches to the
// method. The C ABI, the CLI and the tests all come through here, so a
// parameter is checked in one place.
#pragma once

#include "core/heightfield.hpp"
#include "fracterra/terrain.h"
#include "terrain/profile.hpp"
#include "terrain/terrain_method.hpp"  // dyadic_levels

namespace ft::terrain {

inline constexpr int kMaxLevels = 15;         // 32769^2 floats = 4 GiB
// Windows never hold the whole terrain: midpoint and additions reach 24
// levels (16,777,217 samples a side; row and column keys of the random
// streams stay 32-bit), the other methods the same side.
inline constexpr int kMaxWindowLevels = 24;
inline constexpr int64_t kMaxWindowSide = (int64_t(1) << kMaxWindowLevels) + 1;

ft_terrain_params default_terrain_params();
// Throws ft::Error (FT_ERR_INVALID_ARGUMENT / FT_ERR_TOO_LARGE) with a message
// naming the parameter and its allowed range.
void validate_terrain_params(const ft_terrain_params& p);
Heightfield generate_terrain(const ft_terrain_params& p);

// The whole terrain's samples per side at level of detail `lod` (every
// 2^lod-th sample; lod 0 is the terrain itself). Validates p for windows.
void terrain_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height);
// The samples [x0, x0 + w) x [y0, y0 + h) of the terrain at level of detail
// `lod` (lod > 0: midpoint and additions only), bit-identical to the same
// samples of generate_terrain(p) wherever that fits in memory. Throws for a
// window outside the terrain, empty or too large, and for spectral synthesis.
// The world size recorded is that of the window's own extent.
Heightfield generate_terrain_window(const ft_terrain_params& p, int lod, int64_t x0, int64_t y0, int32_t w, int32_t h);

ft_profile_params default_profile_params();
void validate_profile_params(const ft_profile_params& p);
// dst holds `count` floats, at least 2^levels + 1.
void generate_profile(const ft_profile_params& p, float* dst, size_t count);

}  // namespace ft::terrain
