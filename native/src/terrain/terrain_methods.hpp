// SPDX-License-Identifier: GPL-3.0-or-later
// The table of terrain methods: one row per method (see terrain_method.hpp).
// It is constexpr so that the parameter table's method masks
// (terrain_params.cpp) are computed from it at compile time. A new method is
// its file (its functions, declared with FT_TERRAIN_METHOD_FUNCTIONS) and its
// row here, with its FT_TERRAIN_* value in fracterra/terrain.h.
#pragma once

#include "terrain/terrain_method.hpp"

// The functions a method's file defines, named after it: name_configure,
// name_validate, name_check_heights, name_generate and name_window.
#define FT_TERRAIN_METHOD_FUNCTIONS(name)                                                 \
  std::any name##_configure(const ft_terrain_params& p);                                 \
  void name##_validate(const std::any& config, int64_t max_side);                        \
  void name##_check_heights(const std::any& config, const ft_terrain_params& p);         \
  Heightfield name##_generate(const std::any& config);                                   \
  Heightfield name##_window(const std::any& config, const Window& w, int lod)

namespace ft::terrain {

FT_TERRAIN_METHOD_FUNCTIONS(diamond_square);  // midpoint and additions (diamond_square_method.cpp)
FT_TERRAIN_METHOD_FUNCTIONS(fbm);             // fbm_method.cpp
FT_TERRAIN_METHOD_FUNCTIONS(spectral);        // spectral_method.cpp
FT_TERRAIN_METHOD_FUNCTIONS(interpolated);    // interpolated_method.cpp
FT_TERRAIN_METHOD_FUNCTIONS(mandelbrot);      // mandelbrot_method.cpp
uint64_t midpoint_window_work_bytes(int lod, int32_t w, int32_t h);
uint64_t additions_window_work_bytes(int lod, int32_t w, int32_t h);
void mandelbrot_height_range(const ft_terrain_params& p, double* lo, double* hi);

// Rows in method order: row i is method i (terrain_method() checks it).
inline constexpr TerrainMethod kTerrainMethods[] = {
    {.item = {FT_TERRAIN_MIDPOINT, "MIDPOINT", "Midpoint",
              "Voss midpoint displacement (diamond-square; Voss 1985, seed 000), (2^levels + 1)^2 samples"},
     .dyadic = true, .tiling = Tiling::kOnRequest, .period_overlap = 1, .reference = true, .lod = true,
     .stages_keep_samples = true, .configure = diamond_square_configure, .validate = nullptr,
     .check_heights = diamond_square_check_heights, .generate = diamond_square_generate,
     .window = diamond_square_window, .extent = dyadic_extent, .window_work_bytes = midpoint_window_work_bytes},
    {.item = {FT_TERRAIN_ADDITIONS, "ADDITIONS", "Additions",
              "Voss's successive random additions (Feder 1988, 13.4, seed 001), (2^levels + 1)^2 samples"},
     .dyadic = true, .tiling = Tiling::kOnRequest, .period_overlap = 1, .reference = true, .lod = true,
     .configure = diamond_square_configure, .validate = nullptr, .check_heights = diamond_square_check_heights,
     .generate = diamond_square_generate, .window = diamond_square_window, .extent = dyadic_extent,
     .window_work_bytes = additions_window_work_bytes},
    {.item = {FT_TERRAIN_FBM, "FBM", "fBm Noise",
              "Sum of noise octaves with gain 2^-H (Quilez 2019, seed 004), any width x height"},
     .tiling = Tiling::kOnRequest, .configure = fbm_configure, .validate = fbm_validate,
     .check_heights = fbm_check_heights, .generate = fbm_generate, .window = fbm_window, .extent = sized_extent},
    {.item = {FT_TERRAIN_SPECTRAL, "SPECTRAL", "Spectral",
              "Inverse-FFT spectral synthesis (Saupe 1988), any width x height, always tiles"},
     .tiling = Tiling::kAlways, .configure = spectral_configure, .validate = nullptr,
     .check_heights = spectral_check_heights, .generate = spectral_generate, .window = nullptr,
     .no_windows = "it is one global FFT, every sample depends on every Fourier coefficient, so a window costs "
                   "the whole terrain",
     .extent = sized_extent},
    {.item = {FT_TERRAIN_INTERPOLATED, "INTERPOLATED", "Interpolated",
              "Saupe's InterpolatedFM (1988): the scale shrinks by 1/lacunarity per cycle (Feder 1988, seed 001)"},
     .tiling = Tiling::kOnRequest, .configure = interpolated_configure, .validate = interpolated_validate,
     .check_heights = interpolated_check_heights, .generate = interpolated_generate, .window = interpolated_window,
     .extent = sized_extent},
    {.item = {FT_TERRAIN_MANDELBROT, "MANDELBROT", "Mandelbrot",
              "The Mandelbrot set's smooth escape time of z <- z^2 + c (seed 002); the set is a plateau"},
     .seeded = false, .tiling = Tiling::kNever, .configure = mandelbrot_configure, .validate = mandelbrot_validate,
     .check_heights = mandelbrot_check_heights, .generate = mandelbrot_generate, .window = mandelbrot_window,
     .extent = sized_extent, .height_range = mandelbrot_height_range},
};

inline constexpr int32_t kTerrainMethodCount = int32_t(std::size(kTerrainMethods));

// Bit m set for every method m whose row passes `has` (the parameter rows' `methods`).
template <class Has>
constexpr uint64_t method_mask(Has has) {
  uint64_t mask = 0;
  for (const TerrainMethod& m : kTerrainMethods)
    if (has(m)) mask |= uint64_t(1) << m.item.value;
  return mask;
}

}  // namespace ft::terrain
