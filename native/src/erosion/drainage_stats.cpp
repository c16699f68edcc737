// Hack's h and the concavity theta of a terrain (see drainage_stats.hpp).
#include "erosion/drainage_stats.hpp"

#include <algorithm>
#include <cmath>
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
    if (area[i] < min_area) continue;
    a_hack.push_back(area[i]);
    l_hack.push_back(length[i]);
    const int32_t r = graph.receiver[i];
    // Slopes of cells the fill raised are float steps across a lake: not channels.
    if (r != int32_t(i) && z[i] == hf.data()[i]) {
      a_slope.push_back(area[i]);
      s_slope.push_back((double(z[i]) - z[r]) / graph.length[i]);
    }
  }
  DrainageStats st;
  std::vector<double> bx, by;
  binned_medians(a_hack, l_hack, bx, by);
  if (bx.size() < 3) invalid("too few channel cells for Hack's law (need 3 area bins of 5 cells; use a larger terrain)");
  auto hack = analysis::fit_loglog(bx, by, "Hack's law");
  st.hack_h = hack.slope;
  st.hack_h_stderr = hack.slope_stderr;
  st.hack_bins = hack.points;
  st.min_area = bx.front();
  st.max_area = bx.back();
  bx.clear();
  by.clear();
  binned_medians(a_slope, s_slope, bx, by);
  if (bx.size() < 3) invalid("too few channel cells for the slope-area fit (need 3 area bins of 5 cells)");
  auto flint = analysis::fit_loglog(bx, by, "slope-area");
  st.theta = -flint.slope;
  st.theta_stderr = flint.slope_stderr;
  st.theta_bins = flint.points;
  return st;
}

}  // namespace ft::erosion
