// SPDX-License-Identifier: GPL-3.0-or-later
// Saupe's InterpolatedFM in 2D, Feder's lacunarity variant of the successive
// random additions (seed 001, end of 13.4): start from the four corners;
// each cycle shrinks the grid spacing by a factor r = 1 / lacunarity,
// interpolates the old grid onto the finer one, and adds an independent
// Gaussian to *all* points with the standard deviation the scale change
// implies for fBm, delta ~ spacing^H. The last cycle lands on the sample grid.
// lacunarity 2 is Voss's halving; other values change the lacunarity of the
// landscape and, since the grids no longer nest, spread out the creases the
// plain additions algorithm leaves along its grid lines.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "core/progress.hpp"

namespace ft::terrain {

inline constexpr double kMaxInterpolatedLacunarity = 16.0;

struct InterpolatedConfig {
  int32_t width = 513, height = 513;
  double lacunarity = 2.0;  // 1/r: spacing ratio per cycle, in (1, 16]
  double hurst = 0.8;
  double sigma = 1.0;       // std of the corner values
  uint64_t seed = 1;
  bool periodic = false;    // wrap-around interpolation: the terrain tiles
  int threads = 0;
  Progress progress;
};

// Throws unless lacunarity is finite and in (1, 16].
void check_interpolated_lacunarity(double lacunarity);
// Callers validate (terrain.cpp).
Heightfield interpolated_fm(const InterpolatedConfig& c);
// The w x h samples from (x0, y0) of interpolated_fm(c), bit for bit: each
// cycle computes only the nodes the window's samples reach through the
// interpolation taps. Callers validate.
Heightfield interpolated_window(const InterpolatedConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h);

}  // namespace ft::terrain
