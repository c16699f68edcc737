// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_planet_params (fracterra/params.h): every field's default,
// range, unit and label, for the C ABI's init and range checks, the flags of
// `fracterra planet`, the ctypes Structure and the add-on.
#pragma once

#include "core/param_table.hpp"
#include "fracterra/planet.h"
#include "planet/planet.hpp"

namespace ft::planet {

const ParamTable& planet_param_table();

// The caller's struct (any older size) checked against the table's ranges,
// as a configuration; validate_planet() then checks what relates fields.
PlanetConfig from_c(const ft_planet_params& given);

}  // namespace ft::planet
