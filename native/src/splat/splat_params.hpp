// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_splat_params (fracterra/params.h, FT_PARAMS_SPLAT): every
// field of a layer's rule with its default, range, unit and doc. The rules
// JSON (rules_json.hpp), the C ABI's init and range checks, and later the
// Blender and POV-Ray materials read their fields from it.
#pragma once

#include <vector>

#include "core/param_table.hpp"
#include "fracterra/splat.h"

namespace ft::splat {

const ParamTable& splat_param_table();

// The table's ranges, min <= max of each band, and names unique (when
// given) for every layer of a rule set of 1..kMaxLayers layers. Throws
// naming the layer (by name or index) and the field.
void validate_layers(const ft_splat_params* layers, int32_t count);

inline constexpr int32_t kMaxLayers = 64;

}  // namespace ft::splat
