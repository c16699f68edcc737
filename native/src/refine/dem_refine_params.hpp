// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_dem_refine_params (fracterra/params.h), and the struct
// turned into DemRefineConfig after the table's range checks (for the C ABI
// and the CLI alike).
#pragma once

#include <cstdint>

#include "core/param_table.hpp"
#include "fracterra/raster.h"
#include "refine/dem_refine.hpp"

namespace ft::refine {

// The values of `method`: FT_TERRAIN_MIDPOINT and FT_TERRAIN_ADDITIONS
// (terrain.h belongs to terrain/; capi/ asserts that they agree).
constexpr int32_t kRefineMidpoint = 0, kRefineAdditions = 1;

const ParamTable& dem_refine_param_table();

DemRefineConfig dem_refine_config(const ft_dem_refine_params& p);

}  // namespace ft::refine
