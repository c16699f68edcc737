// SPDX-License-Identifier: GPL-3.0-or-later
// The aligned variogram (or madogram) of a surface too large for memory,
// from windows of it: each window adds the increments whose start node it
// owns, and the sums over all windows are the whole's sums, so H (and
// D = 3 - H) come out equal to estimate_hurst_surface on the whole, up to
// the order of the floating-point additions.
//
// Windows are the tiles of a tile set, sharing their edge samples: a window
// owns the start nodes [x0, x0 + w - 1) x [y0, y0 + h - 1), plus its last
// column (row) when that is the whole's last, so every pair of the dyadic
// grid is counted once. Only aligned methods work this way: their pairs join
// nodes of the tau grid, and a lag that divides the tile size never leaves
// the tile (a window a pair leaves is refused).
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/hurst.hpp"

namespace ft::analysis {

// The lags estimate_hurst_surface uses on a whole_width x whole_height
// surface with these options; the method must be an aligned one.
std::vector<int64_t> surface_lags(const HurstOptions& o, int64_t whole_width, int64_t whole_height);

// Adds the window's share of the increment sums to sum[k], count[k] (k over
// `lags`). The window is `win`, placed at (x0, y0) in the whole.
void add_window_increments(const Heightfield& win, HurstMethod m, int64_t x0, int64_t y0, int64_t whole_width,
                           int64_t whole_height, const std::vector<int64_t>& lags, double* sum, double* count);

// The estimate from the reduced sums (a surface: D = 3 - H).
HurstEstimate estimate_from_increments(HurstMethod m, const std::vector<int64_t>& lags, const double* sum,
                                       const double* count);

}  // namespace ft::analysis
