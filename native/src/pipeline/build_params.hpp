// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_build_params (fracterra/params.h): the pipeline's own
// settings, for ft_build_params_init, the range checks, `fracterra params`,
// the CLI's flags and the ctypes Structure.
#pragma once

#include <string>

#include "core/param_table.hpp"
#include "fracterra/pipeline.h"

namespace ft::pipeline {

const ParamTable& build_param_table();
// "valleys" for FT_EROSION_PRESET_VALLEYS (ft_erosion_preset's name); "" for NONE.
std::string erosion_preset_name(int32_t preset);

}  // namespace ft::pipeline
