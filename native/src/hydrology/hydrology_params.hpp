// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_hydrology_params (fracterra/params.h): every field's
// default, range, unit and label, for the C ABI's init and range checks,
// the CLI's flags of `fracterra rivers`, the ctypes Structure and the add-on.
#pragma once

#include "core/param_table.hpp"
#include "fracterra/hydrology.h"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

const ParamTable& hydrology_param_table();

// Between the C struct and the configuration; from_c checks the table's
// ranges (the checks against the terrain are validate()'s).
ft_hydrology_params to_c(const HydrologyConfig& c);
HydrologyConfig from_c(const ft_hydrology_params& p);

}  // namespace ft::hydrology
