// SPDX-License-Identifier: GPL-3.0-or-later
// Box-counting dimension of a set of polylines in the x,y plane (seed 003,
// eq. 4a, fitted over a range of box sizes instead of one pair): N(eps), the
// number of eps x eps grid boxes the curves pass through, grows like
// eps^-D, so D is the slope of log N against log(1/eps).
//
// Segments are rasterised exactly (every box a segment crosses is counted,
// not only the boxes holding vertices), so a coarse polyline of long straight
// segments still counts as a line. All polylines of the set count together
// (a coastline of several islands is one set).
//
// Box sizes (the documented rule, used when min_size / max_size are 0):
//   E = max(x extent, y extent) of the set;
//   eps_k = max_size * 2^(-k / sizes_per_octave), k = 0, 1, ...
//   max_size = E / 4: boxes larger than a quarter of the extent hold the
//              whole curve in a handful of boxes and only measure its outline;
//   min_size = max(2 * median segment length, E / 2^16): below the segment
//              length a prefractal is made of straight pieces and N grows like
//              1/eps (D -> 1) whatever its dimension; E / 2^16 bounds the cost.
// Each size is counted on `grid_shifts` grids whose origin moves along the
// diagonal by eps / grid_shifts; the smallest count is kept (the covering
// closest to the optimal one, which removes most of the grid-placement noise).
#pragma once

#include <cstdint>
#include <vector>

#include "core/polyline_set.hpp"

namespace ft::analysis {

struct BoxCountOptions {
  double min_size = 0.0;     // smallest box side; 0: automatic (see above)
  double max_size = 0.0;     // largest box side; 0: automatic (E / 4)
  int sizes_per_octave = 2;  // box sizes per halving, 1..16
  int grid_shifts = 4;       // grid origins tried per size, 1..64
};

struct BoxCountResult {
  double dimension = 0.0;       // D: least-squares slope of log N against log(1/eps)
  double std_error = 0.0;       // standard error of that slope (from the fit residuals)
  double min_size = 0.0;        // range actually used
  double max_size = 0.0;
  std::vector<double> sizes;    // eps_k, decreasing
  std::vector<int64_t> counts;  // N(eps_k)
};

// Throws ft::Error (FT_ERR_INVALID_ARGUMENT) for an empty or degenerate set
// (all vertices coincide), non-finite coordinates, bad options, or a size
// range that holds fewer than 3 box sizes.
BoxCountResult box_counting_dimension(const PolylineSet& set, const BoxCountOptions& options = {});

// Number of eps x eps boxes of the grid with origin (ox, oy) that the
// segments of `set` pass through (x, y only). Exposed for tests and for
// callers that want their own size rule.
int64_t count_boxes(const PolylineSet& set, double eps, double ox, double oy);

// Least-squares line y = a + b x; returns b and its standard error.
struct SlopeFit {
  double slope = 0.0, intercept = 0.0, std_error = 0.0;
};
SlopeFit fit_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace ft::analysis
