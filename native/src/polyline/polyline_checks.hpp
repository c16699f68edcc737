// SPDX-License-Identifier: GPL-3.0-or-later
// The checks of ft_polyline_params that relate fields to each other (the
// ranges of single fields come from its table, polyline_params.cpp): the base
// polyline, the FPL 3D plane, the depth each method allows, and the size of
// the result before anything is made.
#pragma once

#include "fracterra/polyline.h"

namespace ft::polyline {

void check_polyline_cross_fields(const ft_polyline_params& p);

}  // namespace ft::polyline
