// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_polyline_params (fracterra/params.h).
#pragma once

#include "core/param_table.hpp"

namespace ft::polyline {

const ParamTable& polyline_param_table();

}  // namespace ft::polyline
