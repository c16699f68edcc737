// SPDX-License-Identifier: GPL-3.0-or-later
// Constants of the landscape model that its run on the model's grid
// (landscape.cpp) and the detail run (detail_run.cpp) share.
#pragma once

#include <cstdint>

namespace ft::erosion {

// A deposit stays this slope (rise over run) below the cell its sediment
// came from, so a fan slopes away from its apex.
inline constexpr double kFanSlope = 0.01;
// An edge cell that gathers the water of this many cells or more is where
// water leaves the map (an outlet). At 8 cells, edge cells that became
// outlets later in the run had risen first: outlets rose by up to 5 cm.
inline constexpr double kOutletCells = 2.0;
// The most steps of one run: Rho8's numbers of step s of run r are drawn at
// level r x kMaxModelSteps + s (the model's run is r = 0, the detail run 1).
inline constexpr int32_t kMaxModelSteps = 32;

}  // namespace ft::erosion
