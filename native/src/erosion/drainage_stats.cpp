// SPDX-License-Identifier: GPL-3.0-or-later
// Hack's h and the concavity theta of a terrain (see drainage_stats.hpp).
#include "erosion/drainage_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <vector>

#include "analysis/loglog_fit.hpp"
#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/flow_graph.hpp"

namespace ft::erosion {
namespace {

// Median of y in each 0.1-decade bin of x (x >= lo), bins with >= 5 values.
void binned_medians(const std::vector<double>& x, const std::vector<double>& y, std::vector<double>& bx,
                    std::vector<double>& by) {
  std::map<int, std::vector<std::pair<double, double>>> bins;
  for (size_t i = 0; i < x.size(); ++i) bins[int(std::floor(std::log10(x[i]) * 10.0))].push_back({x[i], y[i]});
  for (auto& [key, v] : bins) {
    if (v.size() < 5) continue;
    std::vector<double> xs, ys;
    for (auto& [a, b] : v) xs.push_back(a), ys.push_back(b);
    auto med = [](std::vector<double>& u) {
      std::sort(u.begin(), u.end());
      const size_t m = u.size() / 2;
      return u.size() % 2 ? u[m] : 0.5 * (u[m - 1] + u[m]);
    };
    bx.push_back(med(xs));
    by.push_back(med(ys));
  }
}

}  // namespace

ConcavityFit concavity_fit(const std::vector<double>& area, const std::vector<double>& slope) {
  std::vector<double> bx, by;
  binned_medians(area, slope, bx, by);
  if (bx.size() < 3) invalid("too few channel cells for the slope-area fit (need 3 area bins of 5 cells)");
  // The fluvial regime starts at the turnover of the slope-area plot: below
  // it slopes grow with area (diffusive, convex hillslopes), beyond it they
  // fall (Montgomery & Foufoula-Georgiou 1993; Tucker & Bras 1998); studies
  // of channel concavity fit only above such a critical area (Wobus et al.
  // 2006). The fit starts at the bin of the steepest median slope, searched
  // among bins at least a decade below the largest area so that a decade is
  // always fitted (a plot with no turnover keeps its first bin).
  size_t first = 0;
  for (size_t k = 1; k < bx.size() && bx[k] * 10.0 <= bx.back(); ++k)
    if (by[k] > by[first]) first = k;
  bx.erase(bx.begin(), bx.begin() + std::ptrdiff_t(first));
  by.erase(by.begin(), by.begin() + std::ptrdiff_t(first));
  const analysis::LogLogFit f = analysis::fit_loglog(bx, by, "slope-area");
  return {-f.slope, f.slope_stderr, f.points, bx.front()};
}

DrainageStats drainage_stats(const Heightfield& hf, bool periodic, double min_area_cells) {
  check_range("min_area_cells", min_area_cells, 2.0, 1e12);
  const D8Grid g = grid_of(hf, periodic);
  std::vector<float> z(hf.data(), hf.data() + hf.size());
  for (float v : z)
    if (!std::isfinite(v)) invalid("drainage statistics need finite heights");
  FlowGraph graph;
  const int32_t sink = periodic ? periodic_sink(g, z.data()) : -1;
  route_filled(g, z.data(), sink, graph);
  std::vector<double> area;
  accumulate_area(g, graph, area);
  // Longest flow path upstream of each cell, up the stack in reverse.
  const size_t n = g.size();
  std::vector<double> length(n, 0.0);
  for (size_t k = n; k-- > 0;) {
    const int32_t i = graph.stack[k];
    const int32_t r = graph.receiver[i];
    if (r != i) length[r] = std::max(length[r], length[i] + graph.length[i]);
  }
  const double min_area = min_area_cells * g.spacing * g.spacing;
  std::vector<double> a_hack, l_hack, a_slope, s_slope;
  for (size_t i = 0; i < n; ++i) {
    // A cell the fill raised lies in a lake: its receiver, area and length
    // are the fill's flood order (straight rays from the spill, each with
    // L ~ A), not a channel's, and its slope is a float step. Counted in
    // Hack's law, the rays of the lakes bent it (see the header).
    if (area[i] < min_area || z[i] != hf.data()[i]) continue;
    a_hack.push_back(area[i]);
    l_hack.push_back(length[i]);
    const int32_t r = graph.receiver[i];
    if (r != int32_t(i)) {
      a_slope.push_back(area[i]);
      s_slope.push_back((double(z[i]) - z[r]) / graph.length[i]);
    }
  }
  DrainageStats st;
  std::vector<double> bx, by;
  binned_medians(a_hack, l_hack, bx, by);
  if (bx.size() < 3) invalid("too few channel cells outside lakes for Hack's law (need 3 area bins of 5 cells; use a larger terrain)");
  auto hack = analysis::fit_loglog(bx, by, "Hack's law");
  st.hack_h = hack.slope;
  st.hack_h_stderr = hack.slope_stderr;
  st.hack_bins = hack.points;
  st.min_area = bx.front();
  st.max_area = bx.back();
  const ConcavityFit flint = concavity_fit(a_slope, s_slope);
  st.theta = flint.theta;
  st.theta_stderr = flint.theta_stderr;
  st.theta_bins = flint.bins;
  st.theta_min_area = flint.min_area;
  return st;
}

}  // namespace ft::erosion
