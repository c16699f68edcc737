// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_erosion_params (fracterra/params.h): every field's
// default, range, unit and labels, for the C ABI's init and range checks,
// the ctypes binding's Structure and the Blender add-on's properties.
#pragma once

#include "core/param_table.hpp"
#include "erosion/erosion.hpp"
#include "fracterra/erosion.h"

namespace ft::erosion {

const ParamTable& erosion_param_table();

// The sea's choices, for erosion's table and the rivers' (hydrology/): the
// values of Sea (sea.hpp), which are those of FT_WATER_SEA_* (hydrology.h).
inline constexpr ft_param_enum_item kSeaItems[] = {
    {int32_t(Sea::kNone), "NONE", "None", "No sea"},
    {int32_t(Sea::kHeight), "HEIGHT", "Height", "The sea is below a height"},
    {int32_t(Sea::kFraction), "FRACTION", "Fraction", "The sea is below the height with that fraction of the "
                                                      "samples below it"},
};

// Between the C struct and the configuration (fields the struct lacks keep
// their defaults).
ft_erosion_params to_c(const ErosionConfig& c);
ErosionConfig from_c(const ft_erosion_params& p);

}  // namespace ft::erosion
