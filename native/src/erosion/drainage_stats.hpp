// Drainage statistics: what real landscapes are measured by.
//   Hack's law  L ~ A^h: L the main-stream length (the longest flow path
//               upstream of a cell, to the divide), A its drainage area;
//               real basins give h of about 0.5-0.6 (Hack 1957; Rigon et al. 1996).
//   Flint's law S ~ A^-theta: channel slope against drainage area; real
//               channels give theta of about 0.35-0.7 (Flint 1974; Whipple 2004).
// Both are log-log fits over channel cells (area >= min_area), on the
// median of each bin of log area (bins of 0.1 decade holding >= 5 cells),
// so the countless small-area cells do not swamp the fit.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"

namespace ft::erosion {

struct DrainageStats {
  double hack_h = 0, hack_h_stderr = 0;
  double theta = 0, theta_stderr = 0;
  int32_t hack_bins = 0, theta_bins = 0;
  double min_area = 0, max_area = 0;  // range of areas fitted (world units^2)
};

// min_area_cells: the smallest drainage area counted as a channel, in cells
// (>= 2). Throws FT_ERR_INVALID_ARGUMENT when fewer than 3 bins qualify.
DrainageStats drainage_stats(const Heightfield& hf, bool periodic, double min_area_cells = 20.0);

}  // namespace ft::erosion
