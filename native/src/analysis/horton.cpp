// SPDX-License-Identifier: GPL-3.0-or-later
// Horton's bifurcation and length ratios (see horton.hpp).
#include "analysis/horton.hpp"

#include <cmath>
#include <string>

#include "analysis/loglog_fit.hpp"
#include "core/error.hpp"

namespace ft::analysis {

HortonRatios horton_ratios(const std::vector<NetworkStream>& streams) {
  HortonRatios h;
  for (const NetworkStream& s : streams) h.orders = std::max(h.orders, s.order);
  if (h.orders < 2)
    invalid("Horton's ratios need a network with at least two Strahler orders, got " + std::to_string(h.orders) +
            ": give a smaller channel-head area");
  h.streams.assign(size_t(h.orders), 0);
  h.mean_length.assign(size_t(h.orders), 0.0);
  for (const NetworkStream& s : streams) {
    if (s.order < 1) invalid("a Strahler order must be >= 1, got " + std::to_string(s.order));
    ++h.streams[size_t(s.order - 1)];
    h.mean_length[size_t(s.order - 1)] += s.length;
  }
  for (int32_t k = 0; k < h.orders; ++k)
    if (h.streams[size_t(k)] > 0) h.mean_length[size_t(k)] /= double(h.streams[size_t(k)]);
  h.fitted_orders = h.orders == 2 ? 2 : h.orders - 1;
  // log y against k: fit_loglog's x is e^k.
  std::vector<double> x, n, l;
  for (int32_t k = 1; k <= h.fitted_orders; ++k) {
    x.push_back(std::exp(double(k)));
    n.push_back(double(h.streams[size_t(k - 1)]));
    l.push_back(h.mean_length[size_t(k - 1)]);
  }
  const LogLogFit fn = fit_loglog(x, n, "Horton's bifurcation ratio");
  const LogLogFit fl = fit_loglog(x, l, "Horton's length ratio");
  h.bifurcation = std::exp(-fn.slope);
  h.bifurcation_stderr = fn.slope_stderr;
  h.length = std::exp(fl.slope);
  h.length_stderr = fl.slope_stderr;
  return h;
}

}  // namespace ft::analysis
