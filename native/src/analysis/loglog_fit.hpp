// SPDX-License-Identifier: GPL-3.0-or-later
// Ordinary least squares of log(y) against log(x): every estimator of H or D
// is the slope of such a fit, and reports the slope's standard error.
#pragma once

#include <vector>

namespace ft::analysis {

struct LogLogFit {
  double slope = 0, intercept = 0;  // log(y) ~ intercept + slope log(x), natural logs
  double slope_stderr = 0;          // sqrt(residual variance / Sxx); 0 with 2 points
  int points = 0;                   // pairs used (finite, x > 0, y > 0)
};

// Points with x <= 0, y <= 0 or non-finite values are skipped. Throws
// FT_ERR_INVALID_ARGUMENT naming `what` when fewer than 2 usable points remain.
LogLogFit fit_loglog(const std::vector<double>& x, const std::vector<double>& y, const char* what);

}  // namespace ft::analysis
