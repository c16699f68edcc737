// SPDX-License-Identifier: GPL-3.0-or-later
// One octave of a flat fbm, as the octave loop (fbm.cpp) and the explicit
// SIMD rows (basis_simd.cpp) read it.
#pragma once

#include <cstdint>

namespace ft::noise::detail {

// The affine map from normalised (u, v) to lattice coordinates, the
// octave's hash key and, when periodic, its lattice period.
struct Octave {
  float a11 = 1, a12 = 0, a21 = 0, a22 = 1, ox = 0, oy = 0;
  float amp = 1;
  uint32_t key = 0;
  int32_t px = 1, py = 1;    // periods in cells (periodic only)
  float ipx = 1, ipy = 1;    // 1 / period
};

}  // namespace ft::noise::detail
