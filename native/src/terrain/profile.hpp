// SPDX-License-Identifier: GPL-3.0-or-later
// Voss midpoint displacement in 1D (seed 000, eq. 24):
//   X(mid) = (X(left) + X(right)) / 2 + 2^(-sH) sigma rho g,  rho = sqrt(1 - 2^(2H-2)),
// at step s, from X(0) = 0 and X(1) = sigma g, or from 2^m + 1 reference
// values taken as steps 1..m.
#pragma once

#include <cstdint>

#include "core/progress.hpp"

namespace ft::terrain {

inline constexpr int kMaxProfileLevels = 28;  // 2^28 + 1 floats = 1 GiB

struct ProfileConfig {
  int levels = 10;
  double hurst = 0.8;
  double sigma = 1.0;
  uint64_t seed = 1;
  const float* reference = nullptr;  // 2^ref_levels + 1 values
  int ref_levels = 0;
  Progress progress;
};

// Writes 2^levels + 1 samples into dst.
void midpoint_profile(const ProfileConfig& config, float* dst);

}  // namespace ft::terrain
