// SPDX-License-Identifier: GPL-3.0-or-later
// Hurst estimation entry points: band defaults and checks, the slope -> H
// conversion of each method, and the dispatch for profiles and surfaces.
#include "analysis/hurst.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace ft::analysis {

const char* hurst_method_name(HurstMethod m) {
  switch (m) {
    case HurstMethod::kVariogram: return "variogram";
    case HurstMethod::kMadogram: return "madogram";
    case HurstMethod::kVariogramAligned: return "variogram_aligned";
    case HurstMethod::kMadogramAligned: return "madogram_aligned";
    case HurstMethod::kSpectral: return "spectral";
  }
  return "unknown";
}

bool hurst_method_uses_lags(HurstMethod m) { return m != HurstMethod::kSpectral; }

namespace detail {

void check_all_finite(const float* v, size_t n, const char* what) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i]))
      invalid(std::string(what) + " sample " + std::to_string(i) + " is " + format_number(v[i]) +
              "; Hurst estimation needs finite samples");
}

Band resolve_band(const HurstOptions& o, size_t n) {
  const double len = double(n);
  if (hurst_method_uses_lags(o.method)) {
    check_range("lag_min", o.lag_min, 0, len - 2);
    check_range("lag_max", o.lag_max, 0, len - 1);
    // Lags are whole samples: a bound in (0, 1) names none (and a subnormal
    // lag_min made the lag ladder below climb for ever).
    for (const auto& [name, v] : {std::pair{"lag_min", o.lag_min}, std::pair{"lag_max", o.lag_max}})
      if (v > 0 && v < 1)
        invalid(std::string(name) + " must be 0 (the default) or at least 1 sample, got " + format_number(v));
    Band b{o.lag_min > 0 ? o.lag_min : 1.0, o.lag_max > 0 ? o.lag_max : std::max(2.0, std::floor((len - 1) / 16))};
    if (!(b.lo < b.hi))
      invalid("the lag band [" + format_number(b.lo) + ", " + format_number(b.hi) +
              "] is empty; lag_min must be below lag_max (and lag_max at most n - 1 = " + format_number(len - 1) + ")");
    return b;
  }
  const double half = std::floor(len / 2);
  check_range("freq_min", o.freq_min, 0, half - 1);
  check_range("freq_max", o.freq_max, 0, half);
  Band b{o.freq_min > 0 ? o.freq_min : std::clamp(std::floor(len / 128), 1.0, 8.0),
         o.freq_max > 0 ? o.freq_max : std::max(2.0, std::floor(len / 8))};
  if (!(b.lo < b.hi))
    invalid("the frequency band [" + format_number(b.lo) + ", " + format_number(b.hi) +
            "] cycles per record is empty; freq_min must be below freq_max <= n / 2 = " + format_number(half));
  return b;
}

std::vector<int64_t> lags_in_band(HurstMethod m, Band b) {
  std::vector<int64_t> lags;
  if (m == HurstMethod::kVariogramAligned || m == HurstMethod::kMadogramAligned) {
    for (int64_t t = 1; double(t) <= b.hi; t *= 2)
      if (double(t) >= b.lo) lags.push_back(t);
  } else {
    // Quarter-octave steps from lo; the loop ends on the lag itself, which
    // grows (lo >= 1): once the unrounded lag is past hi + 1/2, so is every
    // rounded one (and llround never sees a value out of its range).
    for (int k = 0;; ++k) {
      const double x = b.lo * std::exp2(k / 4.0);
      if (!(x <= b.hi + 0.5)) break;
      const int64_t t = std::llround(x);
      if (double(t) > b.hi) break;
      if (lags.empty() || t > lags.back()) lags.push_back(t);
    }
  }
  if (lags.size() < 2)
    invalid(std::string("the lag band [") + format_number(b.lo) + ", " + format_number(b.hi) + "] holds " +
            std::to_string(lags.size()) + " lag(s) of the " + hurst_method_name(m) +
            " method (aligned methods use powers of two); widen it to hold at least 2");
  return lags;
}

void finish_estimate(HurstEstimate& e) {
  switch (e.method) {
    case HurstMethod::kVariogram:
    case HurstMethod::kVariogramAligned:  // 0.5 E[dX^2] ~ tau^(2H)
      e.hurst = e.fit.slope / 2, e.std_error = e.fit.slope_stderr / 2;
      break;
    case HurstMethod::kMadogram:
    case HurstMethod::kMadogramAligned:  // E|dX| ~ tau^H
      e.hurst = e.fit.slope, e.std_error = e.fit.slope_stderr;
      break;
    case HurstMethod::kSpectral:  // P ~ f^-(2H + 1)
      e.hurst = (-e.fit.slope - 1) / 2, e.std_error = e.fit.slope_stderr / 2;
      break;
  }
  e.dimension = e.topological_dim + 1 - e.hurst;
}

HurstEstimate estimate_transect(const float* v, size_t n, ptrdiff_t stride, const HurstOptions& o) {
  HurstEstimate e;
  e.method = o.method;
  const Band band = resolve_band(o, n);
  if (o.method == HurstMethod::kSpectral) {
    std::vector<double> power(n / 2 + 1, 0.0);
    add_periodograms(v, n, stride, 1, 0, power.data());
    fit_spectrum(power, band, e);
    e.band_lo = band.lo, e.band_hi = band.hi;
  } else {
    const std::vector<int64_t> lags = lags_in_band(o.method, band);
    std::vector<double> sum(lags.size(), 0.0), count(lags.size(), 0.0);
    add_increments(v, n, stride, o.method, lags, sum.data(), count.data());
    for (size_t k = 0; k < lags.size(); ++k) e.x.push_back(double(lags[k])), e.y.push_back(sum[k] / count[k]);
    e.fit = fit_loglog(e.x, e.y, "Hurst estimate (is the input constant?)");
    e.band_lo = double(lags.front()), e.band_hi = double(lags.back());
  }
  finish_estimate(e);
  return e;
}

HurstEstimate transect_median(const Heightfield& hf, const HurstOptions& o);  // transect_median.cpp

}  // namespace detail

HurstEstimate estimate_hurst_profile(const float* values, size_t n, const HurstOptions& options) {
  check_not_null("values", values);
  if (n < 8) invalid("a profile needs at least 8 samples for a Hurst estimate, got " + std::to_string(n));
  analysis::detail::check_all_finite(values, n, "profile");
  return analysis::detail::estimate_transect(values, n, 1, options);
}

HurstEstimate estimate_hurst_surface(const Heightfield& hf, const HurstOptions& o) {
  const int64_t w = hf.width(), h = hf.height();
  if (w < 8 || h < 8)
    invalid("a heightfield needs at least 8 x 8 samples for a Hurst estimate, got " + std::to_string(w) + " x " +
            std::to_string(h));
  analysis::detail::check_all_finite(hf.data(), hf.size(), "heightfield");
  if (o.transects) return detail::transect_median(hf, o);
  HurstEstimate e;
  e.method = o.method;
  e.topological_dim = 2;
  if (o.method == HurstMethod::kSpectral) {
    // Rows and columns pooled when they have the same length (same
    // frequencies per record); otherwise the longer direction only.
    const size_t n = size_t(std::max(w, h));
    const analysis::detail::Band band = analysis::detail::resolve_band(o, n);
    std::vector<double> power(n / 2 + 1, 0.0);
    if (w >= h) analysis::detail::add_periodograms(hf.data(), size_t(w), 1, size_t(h), w, power.data());
    if (h >= w) analysis::detail::add_periodograms(hf.data(), size_t(h), w, size_t(w), 1, power.data());
    analysis::detail::fit_spectrum(power, band, e);
    e.band_lo = band.lo, e.band_hi = band.hi;
  } else {
    const analysis::detail::Band band = analysis::detail::resolve_band(o, size_t(std::min(w, h)));
    const std::vector<int64_t> lags = analysis::detail::lags_in_band(o.method, band);
    analysis::detail::surface_increments(hf, o.method, lags, e.y);
    e.x.assign(lags.begin(), lags.end());
    e.fit = fit_loglog(e.x, e.y, "Hurst estimate (is the heightfield constant?)");
    e.band_lo = double(lags.front()), e.band_hi = double(lags.back());
  }
  analysis::detail::finish_estimate(e);
  return e;
}

}  // namespace ft::analysis
