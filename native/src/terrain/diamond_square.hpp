// SPDX-License-Identifier: GPL-3.0-or-later
// Voss midpoint displacement in 2D (diamond-square) and Feder's successive
// random additions, from four corners or from a grid of reference points.
// The scheme follows seed 000 and Peitgen & Saupe's MidPointFM2D: per stage
// a square step (centres = mean of 4 corners + delta g) and a diamond step
// (mean of the 4 axis neighbours, 3 on the border, + delta g), delta
// shrinking by 2^(-H/2) before each half-step.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "core/progress.hpp"

namespace ft::terrain {

struct DiamondSquareConfig {
  int levels = 9;          // side = 2^levels + 1
  double hurst = 0.8;
  double sigma = 1.0;      // std of the corners; the first square step uses sigma 2^(-H/2)
  uint64_t seed = 1;
  bool periodic = false;   // wrap-around neighbours; last row/column repeat the first
  bool additions = false;  // Feder: after each half-step add delta g to every point
  int threads = 0;
  // Optional (2^m + 1)^2 reference grid taken as stages 1..m (m = ref_levels).
  const float* reference = nullptr;
  int ref_levels = 0;
  Progress progress;
};

// Validates nothing (callers do, see terrain.cpp); fills a (2^levels + 1)^2 grid.
// The refiner behind it is in refiner.hpp.
Heightfield diamond_square(const DiamondSquareConfig& config);

}  // namespace ft::terrain
