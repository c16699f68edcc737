// SPDX-License-Identifier: GPL-3.0-or-later
// The polyline entry point: validates ft_polyline_params and dispatches to
// the method (fpl.hpp, classic_curves.hpp, ifs.hpp, lightning.hpp, the Voss
// profile). The C ABI, the CLI, the study and the tests all come through
// here, so a parameter is checked in one place.
#pragma once

#include <vector>

#include "core/polyline_set.hpp"
#include "fracterra/polyline.h"
#include "polyline/fpl.hpp"

namespace ft::polyline {

ft_polyline_params default_polyline_params();
// Throws ft::Error (FT_ERR_INVALID_ARGUMENT / FT_ERR_TOO_LARGE) naming the
// parameter and what is allowed.
void validate_polyline_params(const ft_polyline_params& p);
PolylineSet generate_polylines(const ft_polyline_params& p);

// The base polyline of p (the unit segment when p.base is NULL).
std::vector<Vec3> base_points(const ft_polyline_params& p);
// The FPL engine configuration of p (FPL, FPL3D and dragon).
FplConfig fpl_config(const ft_polyline_params& p);

}  // namespace ft::polyline
