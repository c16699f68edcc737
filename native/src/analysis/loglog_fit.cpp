// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/loglog_fit.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace ft::analysis {

LogLogFit fit_loglog(const std::vector<double>& x, const std::vector<double>& y, const char* what) {
  std::vector<double> lx, ly;
  for (size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i]))
      lx.push_back(std::log(x[i])), ly.push_back(std::log(y[i]));
  const size_t n = lx.size();
  if (n < 2)
    invalid(std::string(what) + ": only " + std::to_string(n) +
            " usable point(s) for the log-log fit, at least 2 are needed (is the input constant, or the "
            "band too narrow for its size?)");
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) mx += lx[i], my += ly[i];
  mx /= double(n), my /= double(n);
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; ++i) sxx += (lx[i] - mx) * (lx[i] - mx), sxy += (lx[i] - mx) * (ly[i] - my);
  if (!(sxx > 0)) invalid(std::string(what) + ": all points of the log-log fit share one abscissa");
  LogLogFit f;
  f.points = int(n);
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  if (n > 2) {
    double rss = 0;
    for (size_t i = 0; i < n; ++i) {
      const double r = ly[i] - f.intercept - f.slope * lx[i];
      rss += r * r;
    }
    f.slope_stderr = std::sqrt(rss / double(n - 2) / sxx);
  }
  return f;
}

}  // namespace ft::analysis
