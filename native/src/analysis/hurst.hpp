// SPDX-License-Identifier: GPL-3.0-or-later
// Hurst exponent estimators for profiles (1D) and heightfields (2D).
//
// Every estimator is the slope of a log-log least-squares fit:
//   variogram   0.5 E[(X(t + tau) - X(t))^2] ~ tau^(2H)   -> H = slope / 2
//   madogram    E|X(t + tau) - X(t)|         ~ tau^H      -> H = slope
//   *_aligned   the same, but only increments between points of the dyadic
//               grid of spacing tau (t a multiple of tau, tau = 2^j): the pairs
//               the midpoint and additions methods build with exactly
//               variance sigma^2 tau^(2H) (seed 000, eq. 24)
//   spectral    power spectrum P(f) ~ f^(-B), B = 2H + 1 (seed 004), of the
//               profile or of every row and column of a surface (a straight
//               transect of an isotropic fBm surface is an fBm profile with
//               the same H), linearly detrended and Hann-windowed, averaged
//               in log-spaced bins (8 per octave)        -> H = (B - 1) / 2
// For surfaces, `transects` estimates every row and every column on its own
// and reports the median (the transect-median estimator).
// D = n + 1 - H with n = 1 for profiles and 2 for surfaces (seed 000).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/loglog_fit.hpp"
#include "core/heightfield.hpp"

namespace ft::analysis {

enum class HurstMethod { kVariogram = 0, kMadogram = 1, kVariogramAligned = 2, kMadogramAligned = 3, kSpectral = 4 };

struct HurstOptions {
  HurstMethod method = HurstMethod::kVariogramAligned;
  // Lag band in samples for the increment methods; 0 picks the default:
  // lag_min 1, lag_max (n - 1) / 16 (at least 16 increments at the largest lag
  // along a transect of n samples; at least 2 lags).
  double lag_min = 0, lag_max = 0;
  // Frequency band in cycles per record (per transect length) for the
  // spectral method; 0 picks the default [8, n / 8] (below 8 cycles the Hann
  // window's main lobe biases steep spectra upwards by over 1%; above n / 8
  // aliasing and the interpolation of the generators flatten them).
  double freq_min = 0, freq_max = 0;
  bool transects = false;  // surfaces only: median of the row and column estimates
};

struct HurstEstimate {
  HurstMethod method = HurstMethod::kVariogramAligned;
  bool transects = false;
  int topological_dim = 1;        // n: 1 for profiles, 2 for surfaces
  double hurst = 0, dimension = 0;
  double std_error = 0;        // standard error of H (of the slope, or of the median)
  double band_lo = 0, band_hi = 0;  // lags (samples) or frequencies (cycles per record) fitted
  LogLogFit fit;                  // the fit in natural logs (slope in its own units)
  std::vector<double> x, y;       // the fitted points (lag, statistic) or (frequency, power)
  int transect_count = 0;         // transect-median: transects that gave an estimate
};

const char* hurst_method_name(HurstMethod m);  // "variogram", "madogram_aligned", ...
// true for "lag", false for "frequency".
bool hurst_method_uses_lags(HurstMethod m);

// `values` holds n finite samples, n >= 8.
HurstEstimate estimate_hurst_profile(const float* values, size_t n, const HurstOptions& options);
// Every sample must be finite; width and height >= 8 (>= 8 in the transect
// direction(s) used).
HurstEstimate estimate_hurst_surface(const Heightfield& hf, const HurstOptions& options);

namespace detail {
// The statistic of one method over the given lags/frequencies, for the
// fitting code; shared by profiles, surfaces and transects.
struct Band {
  double lo, hi;
};
Band resolve_band(const HurstOptions& o, size_t n);
// Lags in [lo, hi]: powers of two for aligned methods, otherwise integers
// spaced about 4 per octave.
std::vector<int64_t> lags_in_band(HurstMethod m, Band b);
// Turns a fit of the method's statistic into H and its standard error.
void finish_estimate(HurstEstimate& e);
void check_all_finite(const float* v, size_t n, const char* what);

// Increment statistics (variogram.cpp): sums over one strided transect,
// added to sum[k] and count[k] for lag lags[k].
void add_increments(const float* v, size_t n, ptrdiff_t stride, HurstMethod m, const std::vector<int64_t>& lags,
                    double* sum, double* count);
// Pooled row (x) and column (y) increments of a surface: stat[k] for lags[k].
void surface_increments(const Heightfield& hf, HurstMethod m, const std::vector<int64_t>& lags,
                        std::vector<double>& stat);
// One transect of n samples with the given stride (profiles: stride 1).
HurstEstimate estimate_transect(const float* v, size_t n, ptrdiff_t stride, const HurstOptions& o);
// Spectral (spectrum.cpp): adds the windowed periodogram of `count`
// transects of n samples (transect t starts at v + t * step, stride
// `stride`) to power[1 .. n/2].
void add_periodograms(const float* v, size_t n, ptrdiff_t stride, size_t count, ptrdiff_t step, double* power);
// Log-binned spectrum fitted over [lo, hi] cycles per record.
void fit_spectrum(const std::vector<double>& power, Band band, HurstEstimate& e);
}  // namespace detail

}  // namespace ft::analysis
