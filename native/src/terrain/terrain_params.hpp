// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_terrain_params and ft_profile_params (fracterra/params.h):
// every field's default, range, unit, labels and the methods that use it.
#pragma once

#include "core/param_table.hpp"

namespace ft::terrain {

const ParamTable& terrain_param_table();
const ParamTable& profile_param_table();

}  // namespace ft::terrain
