// SPDX-License-Identifier: GPL-3.0-or-later
// Horton's laws of a river network from its Strahler orders (Horton 1945;
// Strahler 1957): the number N_k of streams of order k falls geometrically,
// N_k ~ R_b^-k (bifurcation ratio R_b), and their mean length L_k grows,
// L_k ~ R_l^k (length ratio R_l). Real networks have R_b about 3-5 and R_l
// about 1.5-3.5. A stream is a maximal run of segments of one order.
#pragma once

#include <cstdint>
#include <vector>

namespace ft::analysis {

struct NetworkStream {
  int32_t order = 1;
  double length = 0;  // the sum of its segments' lengths
};

struct HortonRatios {
  double bifurcation = 0, bifurcation_stderr = 0;  // R_b and the standard error of its log
  double length = 0, length_stderr = 0;            // R_l and the standard error of its log
  int32_t orders = 0;                              // highest order
  int32_t fitted_orders = 0;                       // orders in the fits
  std::vector<int64_t> streams;                    // N_k, k = 1 .. orders
  std::vector<double> mean_length;                 // L_k
};

// The ratios by least squares of log N_k and log L_k against k over the
// orders 1 .. orders - 1 (the highest order's streams are cut by the map's
// edge: their count is the number of outlets, not a bifurcation), or all
// orders when there are only two. Throws FT_ERR_INVALID_ARGUMENT when the
// network has fewer than two orders.
HortonRatios horton_ratios(const std::vector<NetworkStream>& streams);

}  // namespace ft::analysis
