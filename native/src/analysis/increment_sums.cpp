// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/increment_sums.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace ft::analysis {
namespace {

bool is_aligned(HurstMethod m) { return m == HurstMethod::kVariogramAligned || m == HurstMethod::kMadogramAligned; }

inline double term(double d, bool sq) { return sq ? 0.5 * d * d : std::fabs(d); }

// The last start coordinate a window owns along one axis (exclusive end).
int64_t owned_end(int64_t origin, int64_t extent, int64_t whole) {
  return origin + extent == whole ? whole : origin + extent - 1;
}

}  // namespace

std::vector<int64_t> surface_lags(const HurstOptions& o, int64_t whole_width, int64_t whole_height) {
  if (!is_aligned(o.method))
    invalid(std::string("increment sums over windows need an aligned method (variogram_aligned or madogram_aligned); "
                        "got ") + hurst_method_name(o.method));
  if (whole_width < 8 || whole_height < 8) invalid("a surface needs at least 8 x 8 samples for a Hurst estimate");
  const analysis::detail::Band band = analysis::detail::resolve_band(o, size_t(std::min(whole_width, whole_height)));
  return analysis::detail::lags_in_band(o.method, band);
}

void add_window_increments(const Heightfield& win, HurstMethod m, int64_t x0, int64_t y0, int64_t whole_width,
                           int64_t whole_height, const std::vector<int64_t>& lags, double* sum, double* count) {
  const int64_t w = win.width(), h = win.height();
  if (x0 < 0 || y0 < 0 || x0 + w > whole_width || y0 + h > whole_height)
    invalid("the window [" + std::to_string(x0) + ", " + std::to_string(x0 + w) + ") x [" + std::to_string(y0) + ", " +
            std::to_string(y0 + h) + ") is not inside the " + std::to_string(whole_width) + " x " +
            std::to_string(whole_height) + " surface");
  analysis::detail::check_all_finite(win.data(), win.size(), "window");
  const bool sq = m == HurstMethod::kVariogramAligned;
  const int64_t xe = owned_end(x0, w, whole_width), ye = owned_end(y0, h, whole_height);
  for (size_t k = 0; k < lags.size(); ++k) {
    const int64_t tau = lags[k];
    const int64_t first_x = (x0 + tau - 1) / tau * tau, first_y = (y0 + tau - 1) / tau * tau;
    double s = 0, c = 0;
    for (int64_t gy = first_y; gy < ye; gy += tau) {
      const float* row = win.data() + (gy - y0) * w;
      for (int64_t gx = first_x; gx < xe; gx += tau) {
        const float z = row[gx - x0];
        if (gx + tau < whole_width) {
          if (gx + tau >= x0 + w) invalid("lag " + std::to_string(tau) + " leaves the window: lags must divide the tile size");
          s += term(double(row[gx + tau - x0]) - double(z), sq), c += 1;
        }
        if (gy + tau < whole_height) {
          if (gy + tau >= y0 + h) invalid("lag " + std::to_string(tau) + " leaves the window: lags must divide the tile size");
          s += term(double(row[gx - x0 + tau * w]) - double(z), sq), c += 1;
        }
      }
    }
    sum[k] += s;
    count[k] += c;
  }
}

HurstEstimate estimate_from_increments(HurstMethod m, const std::vector<int64_t>& lags, const double* sum,
                                       const double* count) {
  HurstEstimate e;
  e.method = m;
  e.topological_dim = 2;
  for (size_t k = 0; k < lags.size(); ++k) {
    if (!(count[k] >= 0) || !std::isfinite(sum[k])) invalid("increment sums must be finite with counts >= 0");
    e.x.push_back(double(lags[k]));
    e.y.push_back(count[k] > 0 ? sum[k] / count[k] : 0.0);
  }
  e.fit = fit_loglog(e.x, e.y, "Hurst estimate (is the surface constant?)");
  e.band_lo = double(lags.front()), e.band_hi = double(lags.back());
  analysis::detail::finish_estimate(e);
  return e;
}

}  // namespace ft::analysis
