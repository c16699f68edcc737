// SPDX-License-Identifier: GPL-3.0-or-later
// Levels given as absolute heights or as quantiles of the samples ("q0.5" is
// the median), shared by coastlines and clouds.
#pragma once

#include <string>

#include "core/heightfield.hpp"

namespace ft::analysis {

struct LevelSpec {
  double value = 0;
  bool quantile = false;  // value is a fraction in [0, 1]
};

// "12.5" -> absolute 12.5; "q0.25" -> quantile 0.25. Throws
// FT_ERR_INVALID_ARGUMENT naming `what` for anything else.
LevelSpec parse_level(const std::string& text, const char* what);
// The q-quantile of the samples, linearly interpolated between order
// statistics (NumPy's default): q = 0 is the minimum, 1 the maximum.
// NaN samples are refused.
double heightfield_quantile(const Heightfield& hf, double q);
// The absolute height of a level spec.
double resolve_level(const Heightfield& hf, const LevelSpec& spec);

}  // namespace ft::analysis
