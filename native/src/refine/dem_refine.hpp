// SPDX-License-Identifier: GPL-3.0-or-later
// Refining a real DEM: seed 000's midpoint displacement (or Feder's random
// additions) run from the DEM's samples as its reference points, so that a
// measured landscape gets detail finer than its pixels, with the DEM's own
// statistics.
//
// The lattice: the reference grid of the midpoint method is (2^m + 1)^2. A
// square window of that side is cut from the DEM (the largest that fits and
// holds no nodata, the one nearest the centre unless placed by hand); its
// samples are the reference and survive exactly at their nodes. K added
// levels make the side 2^(m + K) + 1.
//
// Automatic statistics (the "measure, then generate" loop of seeds 000 and
// 003/004):
//  - H: the slope of the window's plain variogram (analysis/hurst.hpp,
//    rows and columns pooled, lags 1 .. (side - 1) / 4). The dyadic-aligned
//    variant is meant for terrains built on a dyadic grid; a DEM is not.
//  - sigma: from V1, the DEM's mean squared increment at its finest lag (one
//    pixel, rows and columns pooled). If the DEM is a sample of a surface
//    with increment variance V(r) = V1 r^(2H) (r in DEM pixels), the centre
//    of a pixel square, given its 4 corners, differs from their mean with
//    variance
//        V(1/sqrt 2) - (1/32) (8 V(1) + 4 V(sqrt 2)) = V1 k(H),
//        k(H) = 2^-H - 1/4 - 2^H / 8
//    (the kriging variance of the 4-corner mean). That is the displacement
//    the first added square step must have; the refiner's schedule
//    (square delta of stage s = sigma 2^(-(s - 1) H - H / 2), and the diamond
//    step 2^(-H / 2) smaller, which is the same kriging variance for the
//    diamond's 4 neighbours) then continues it level after level. So
//        sigma = sqrt(V1 k(H)) 2^(m H + H / 2).
//    k(1) = 0: a surface with H = 1 is smooth and gets no detail.
#pragma once

#include <cstdint>

#include "analysis/hurst.hpp"
#include "core/heightfield.hpp"
#include "core/error.hpp"

namespace ft::refine {

// The most levels one refinement adds (the result is also held to the memory cap).
constexpr int kMaxRefineLevels = 12;

struct DemRefineConfig {
  int levels_added = 2;     // K, 1..12 (and the result within the memory cap)
  double hurst = -1;        // H in [0, 1); negative: measured from the DEM
  double sigma = -1;        // > 0; zero or negative: from the DEM (see above)
  uint64_t seed = 1;
  bool additions = false;   // Feder's successive random additions instead of midpoint
  // The window: side 2^m + 1 (0: the largest that fits without nodata) at
  // (x, y), its top-left sample (negative: the valid one nearest the centre).
  int window_side = 0;
  int window_x = -1, window_y = -1;
  int threads = 0;
  ft_progress_fn progress = nullptr;  // optional, may cancel (see core.h)
  void* progress_user = nullptr;
};

struct DemRefineResult {
  Heightfield terrain;  // (2^(m + K) + 1)^2, georeferenced when the DEM was
  int window_x = 0, window_y = 0, window_side = 0;
  double hurst = 0, sigma = 0;
  bool hurst_measured = false, sigma_measured = false;
  analysis::HurstEstimate estimate;  // when hurst_measured
  double v1 = 0;           // the DEM's mean squared increment at one pixel
};

// k(H) above: the variance of a pixel-square centre about its corners' mean,
// per unit of V1.
double centre_kriging_factor(double hurst);
// `dem` may hold NaN (nodata); the window never does.
DemRefineResult refine_dem(const Heightfield& dem, const DemRefineConfig& config);

}  // namespace ft::refine
