// SPDX-License-Identifier: GPL-3.0-or-later
// Drainage statistics: what real landscapes are measured by.
//   Hack's law  L ~ A^h: L the main-stream length (the longest flow path
//               upstream of a cell, to the divide), A its drainage area;
//               real basins give h of about 0.5-0.6 (Hack 1957; Rigon et al. 1996).
//   Flint's law S ~ A^-theta: channel slope against drainage area; real
//               channels give theta of about 0.35-0.7 (Flint 1974; Whipple 2004).
// Both are log-log fits over channel cells (area >= min_area), on the
// median of each bin of log area (bins of 0.1 decade holding >= 5 cells),
// so the countless small-area cells do not swamp the fit. Cells of filled
// lakes are not channels and count in neither: the fill routes a lake along
// straight rays from its spill, each with L ~ A (h = 1), and these bent
// Hack's law wherever lakes are many (the 513^2 example of docs/erosion.md:
// h 0.410 with them, 0.481 without; an fBm before erosion, closed basins on
// 65% of its channel cells, drifted from 0.50 at 129^2 to 0.43 at 513^2).
// The slope-area fit starts at the plot's turnover (the bin of the steepest
// median slope at least a decade below the largest area): below it lies the
// hillslope regime, where slope grows with area, which a fixed cell count
// cuts at another area on every grid (at 1025^2, 20 cells fell inside it and
// theta read 0.23 instead of 0.27).
#pragma once

#include <cstdint>
#include <vector>

#include "core/heightfield.hpp"

namespace ft::erosion {

struct DrainageStats {
  double hack_h = 0, hack_h_stderr = 0;
  double theta = 0, theta_stderr = 0;
  int32_t hack_bins = 0, theta_bins = 0;
  double min_area = 0, max_area = 0;  // range of areas of Hack's fit (world units^2)
  double theta_min_area = 0;          // where the slope-area fit starts: the turnover (world units^2)
};

// The slope-area part: theta of S ~ A^-theta over the given cells (any area
// unit, slopes > 0), fitted from the turnover up; min_area is where the fit
// starts, in the areas' unit. Throws FT_ERR_INVALID_ARGUMENT when fewer than
// 3 bins qualify.
struct ConcavityFit {
  double theta = 0, theta_stderr = 0;
  int32_t bins = 0;
  double min_area = 0;
};
ConcavityFit concavity_fit(const std::vector<double>& area, const std::vector<double>& slope);

// min_area_cells: the smallest drainage area counted as a channel, in cells
// (>= 2). Throws FT_ERR_INVALID_ARGUMENT when fewer than 3 bins qualify.
DrainageStats drainage_stats(const Heightfield& hf, bool periodic, double min_area_cells = 20.0);

}  // namespace ft::erosion
