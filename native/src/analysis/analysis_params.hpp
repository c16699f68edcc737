// SPDX-License-Identifier: GPL-3.0-or-later
// The tables of ft_hurst_params and ft_clouds_params (fracterra/params.h),
// and those structs turned into the estimators' own options after the
// tables' range checks and the checks that relate several fields (for the
// C ABI and the CLI alike).
#pragma once

#include <cstdint>
#include <optional>

#include "analysis/clouds.hpp"
#include "analysis/hurst.hpp"
#include "analysis/hurst_choice.hpp"
#include "core/param_table.hpp"
#include "fracterra/analysis.h"

namespace ft::analysis {

const ParamTable& hurst_param_table();
const ParamTable& clouds_param_table();

// The options for an input of width x height samples (a profile: height 1).
// FT_HURST_AUTO is resolved here and `choice` says what it chose.
HurstOptions hurst_options(const ft_hurst_params& p, int64_t width, int64_t height,
                           std::optional<HurstChoice>& choice);
CloudOptions cloud_options(const ft_clouds_params& p);

}  // namespace ft::analysis
