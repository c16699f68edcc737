// The terrain entry point: validates ft_terrain_params and dispatches to the
// method. The C ABI, the CLI and the tests all come through here, so a
// parameter is checked in one place.
#pragma once

#include "core/heightfield.hpp"
#include "fracterra/terrain.h"
#include "terrain/profile.hpp"

namespace ft {

inline constexpr int kMaxLevels = 15;         // 32769^2 floats = 4 GiB

ft_terrain_params default_terrain_params();
// Throws ft::Error (FT_ERR_INVALID_ARGUMENT / FT_ERR_TOO_LARGE) with a message
// naming the parameter and its allowed range.
void validate_terrain_params(const ft_terrain_params& p);
Heightfield generate_terrain(const ft_terrain_params& p);

ft_profile_params default_profile_params();
void validate_profile_params(const ft_profile_params& p);
// dst holds `count` floats, at least 2^levels + 1.
void generate_profile(const ft_profile_params& p, float* dst, size_t count);

// log2(size - 1) when size is 2^m + 1 with m >= 1, else -1.
int dyadic_levels(int64_t size);

}  // namespace ft
