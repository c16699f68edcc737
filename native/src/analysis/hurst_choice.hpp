// SPDX-License-Identifier: GPL-3.0-or-later
// Which Hurst estimator to trust on a given record: the recommendation the
// CLI's `analyze` and Blender's measure operator both report (FT_HURST_AUTO),
// so one terrain shows one H wherever it is measured.
#pragma once

#include <cstdint>

#include "analysis/hurst.hpp"

namespace ft::analysis {

enum class HurstChoiceReason : int32_t {
  kDyadicGrid = 1,   // 2^n + 1 samples per side: the dyadic-aligned variogram
  kLongRecord = 2,   // otherwise >= 256 samples along the shorter side: the spectral slope
  kShortRecord = 3   // otherwise: the plain variogram
};

struct HurstChoice {
  HurstMethod method;
  HurstChoiceReason reason;
  const char* why;  // static text saying why, for reports and tooltips
};

// A profile of `width` samples has height 1.
HurstChoice choose_hurst_method(int64_t width, int64_t height);

}  // namespace ft::analysis
