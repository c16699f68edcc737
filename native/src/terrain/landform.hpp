// SPDX-License-Identifier: GPL-3.0-or-later
// Landforms: what turns a method's raw heights into a usable landscape
// (levelling, height offset, edge falloff, a flattened sea). Applied after
// the method, to the whole terrain or to a window of it; every step except
// a sea given as a fraction depends only on the sample's position in the
// whole terrain and on the whole's four corners, so a window equals the same
// samples of the whole, bit for bit.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "fracterra/terrain.h"

namespace ft::terrain {

// Bound of |height_offset|, |edge_level| and |sea_level|: far inside float
// range, so adding them keeps the generators' height bound valid.
inline constexpr double kMaxLandformHeight = 1e30;
// Largest side of a custom falloff mask (that of the largest free-size terrain).
inline constexpr int32_t kMaxMaskSide = 65536;

// The whole terrain's corner heights (x, y): (0, 0), (W - 1, 0), (0, H - 1), (W - 1, H - 1).
struct Corners {
  double c00 = 0, c10 = 0, c01 = 0, c11 = 0;
};

// Where the samples of `hf` sit in the whole terrain: sample (i, j) is the
// whole's sample (x0 + i step, y0 + j step) of whole_width x whole_height.
struct Placement {
  int64_t x0 = 0, y0 = 0, step = 1, whole_width = 0, whole_height = 0;
};

// True when the settings change the method's heights at all.
bool has_landforms(const ft_terrain_params& p);
// The cross-field checks: a sea fraction needs the whole terrain; a custom
// falloff needs a mask of 2..65536 per side whose values are all in [0, 1].
void validate_landforms(const ft_terrain_params& p, bool whole);
// The custom falloff mask at (u, v) in [0, 1]^2 of the whole terrain, bilinear.
double mask_weight(const ft_terrain_params& p, double u, double v);
// Levelling, offset and falloff of `hf` placed at `at`, with the whole's corners.
void apply_landforms(const ft_terrain_params& p, const Corners& corners, const Placement& at, Heightfield& hf,
                     int threads);
// The sea (FT_SEA_HEIGHT, or FT_SEA_FRACTION on a whole terrain): heights
// below it become it. Returns the sea's height (NaN without a sea).
double apply_sea(const ft_terrain_params& p, Heightfield& hf);

}  // namespace ft::terrain
