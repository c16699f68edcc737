// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/analysis.h
/// Measures: Hurst exponent and fractal dimension of profiles and
/// heightfields, coastlines (level sets by marching squares) and Feder's
/// clouds.
#ifndef FRACTERRA_ANALYSIS_H
#define FRACTERRA_ANALYSIS_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Hurst estimators (ft_hurst_params.method). Each is the slope of a log-log
/// least-squares fit over a band:
enum {
  FT_HURST_VARIOGRAM = 0,          ///< 0.5 E[(X(t+tau) - X(t))^2] ~ tau^(2H), integer lags ~4 per octave
  FT_HURST_MADOGRAM = 1,           ///< E|X(t+tau) - X(t)| ~ tau^H
  FT_HURST_VARIOGRAM_ALIGNED = 2,  ///< variogram over dyadic-grid pairs only (tau = 2^j, t multiple of tau):
                                   ///< exact for midpoint displacement
  FT_HURST_MADOGRAM_ALIGNED = 3,   ///< madogram over dyadic-grid pairs only
  FT_HURST_SPECTRAL = 4,           ///< power spectrum P(f) ~ f^-(2H + 1) of the profile, or of every row
                                   ///< and column of a surface; detrended, Hann window, 8 log bins per octave
  FT_HURST_AUTO = 5                ///< (ABI 1.2) the recommended one for this input, as `fracterra analyze`
                                   ///< reports it: FT_HURST_VARIOGRAM_ALIGNED on 2^n + 1 samples per side,
                                   ///< else FT_HURST_SPECTRAL from 256 samples on the shorter side, else
                                   ///< FT_HURST_VARIOGRAM. The result's `method` and `auto_reason` say
                                   ///< which and why.
};

/// Why FT_HURST_AUTO chose its estimator (ft_hurst_result.auto_reason).
enum {
  FT_HURST_REASON_NONE = 0,        ///< a method was asked for by name
  FT_HURST_REASON_DYADIC_GRID = 1, ///< 2^n + 1 samples per side: the aligned variogram is exact there
  FT_HURST_REASON_LONG_RECORD = 2, ///< >= 256 samples per side: the spectral slope
  FT_HURST_REASON_SHORT_RECORD = 3 ///< fewer: the plain variogram
};

/// Parameters of the Hurst estimates. Fill with ft_hurst_params_init.
typedef struct ft_hurst_params {
  uint32_t struct_size;   ///< sizeof(ft_hurst_params); set by _init
  int32_t method;         ///< FT_HURST_*; default FT_HURST_VARIOGRAM_ALIGNED (FT_HURST_AUTO
                          ///< recommends one for the input)
  double lag_min;         ///< smallest lag in samples (increment methods); 0 (default) = 1
  double lag_max;         ///< largest lag in samples; 0 (default) = max(2, (n - 1) / 16), n = the
                          ///< profile length or the shorter side of a heightfield
  double freq_min;        ///< spectral: lowest frequency in cycles per record; 0 (default) =
                          ///< clamp(n / 128, 1, 8)
  double freq_max;        ///< spectral: highest frequency, at most n / 2; 0 (default) = n / 8
  int32_t transects;      ///< heightfields: non-zero = median of the estimates of every row and
                          ///< column (transect-median estimator); default 0 (pooled)
} ft_hurst_params;

/// The result of a Hurst estimate (caller-allocated). Set struct_size to
/// sizeof(ft_hurst_result) before the call: a library of a later 2.x fills
/// only what that size holds.
typedef struct ft_hurst_result {
  uint32_t struct_size;    ///< set by the caller (ABI 2.0)
  int32_t method;          ///< the FT_HURST_* used
  int32_t transects;       ///< non-zero for a transect median
  int32_t points;          ///< points in the log-log fit
  double hurst;            ///< H (not clamped: values outside [0, 1] mean the input is not fBm-like)
  double dimension;        ///< D = n + 1 - H, n = 1 for profiles, 2 for heightfields
  double std_error;        ///< standard error of H from the fit's residuals (of the median for
                           ///< transects; transects are correlated, so it is a lower bound)
  double band_lo;          ///< first lag (samples) or lowest frequency (cycles per record) fitted
  double band_hi;          ///< last lag or highest frequency fitted
  int32_t band_is_frequency; ///< 1 for the spectral method, 0 for lags
  int32_t auto_reason;     ///< FT_HURST_REASON_*: why FT_HURST_AUTO chose `method` (NONE otherwise)
  const char* auto_reason_text; ///< the same in words (static storage, never NULL; "" for NONE)
} ft_hurst_result;

FT_API ft_status ft_hurst_params_init(ft_hurst_params* p);
/// Estimates H of a profile of `count` >= 8 finite samples. `samples` and
/// `out` must not be NULL; `params` may be NULL for the defaults.
FT_API ft_status ft_hurst_profile(const float* samples, size_t count, const ft_hurst_params* params,
                                  ft_hurst_result* out);
/// Estimates H of a heightfield of at least 8 x 8 finite samples.
FT_API ft_status ft_hurst_heightfield(const ft_heightfield* hf, const ft_hurst_params* params,
                                      ft_hurst_result* out);
/// ft_hurst_heightfield, with the points it fitted (ABI 2.27): the lags (samples) and the statistic
/// of an increment method, or the frequencies (cycles per record) and the transects' averaged
/// periodogram of the spectral one (~ f^-(2H + 1)), into x[0 .. capacity) and y; *count receives their number (x and y may be
/// NULL with capacity 0 to ask for it; a smaller capacity fails and says how many).
FT_API ft_status ft_hurst_heightfield_points(const ft_heightfield* hf, const ft_hurst_params* params,
                                             ft_hurst_result* out, double* x, double* y, int64_t capacity,
                                             int64_t* count);

/// H of a surface too large for memory, from windows of it (ABI 2.4): the
/// aligned variogram or madogram (params->method FT_HURST_VARIOGRAM_ALIGNED,
/// FT_HURST_MADOGRAM_ALIGNED, or FT_HURST_AUTO on a 2^n + 1 grid) of the
/// whole_width x whole_height surface, over the lags ft_hurst_heightfield
/// would use on the whole. Each window (a tile sharing its edge samples with
/// its neighbours, placed at x0, y0) adds the increments whose start node it
/// owns; the sums of all windows, in any order, give ft_hurst_from_increment_sums
/// the whole's estimate (equal up to the order of the additions). Lags must
/// divide the tile size (a pair leaving its window is refused).
/// `*count` receives the number of lags; `lags` (may be NULL when capacity is 0)
/// receives up to `capacity` of them.
FT_API ft_status ft_increment_lags(const ft_hurst_params* params, int64_t whole_width, int64_t whole_height,
                                   int64_t* lags, size_t capacity, size_t* count);
/// Adds the window's sums to sums[k] and counts[k], k < count (count must be
/// the number of lags of ft_increment_lags). `params` may be NULL (defaults).
FT_API ft_status ft_increment_sums(const ft_heightfield* window, const ft_hurst_params* params, int64_t x0,
                                   int64_t y0, int64_t whole_width, int64_t whole_height, double* sums,
                                   double* counts, size_t count);
/// The estimate (H, D = 3 - H, fit) from the reduced sums of every window.
FT_API ft_status ft_hurst_from_increment_sums(const ft_hurst_params* params, int64_t whole_width,
                                              int64_t whole_height, const double* sums, const double* counts,
                                              size_t count, ft_hurst_result* out);

/// The level set of a heightfield at `level` (or at the `level`-quantile of
/// its samples, level in [0, 1], when level_is_quantile is non-zero) as
/// polylines: x = column, y = row, z = level, land (>= level) on the left, so
/// islands run counter-clockwise and lakes clockwise; closed loops repeat their
/// first vertex; open chains end on the border. Saddles are resolved by the
/// cell mean. A level outside the data range gives an empty set (FT_OK).
/// NaN samples are refused. Free *out with ft_polylines_free.
FT_API ft_status ft_coastline(const ft_heightfield* hf, double level, int32_t level_is_quantile,
                              ft_polylines** out);
/// The level sets at `count` heights `levels` (1..4096 finite values, in any
/// order), one after another, each as ft_coastline gives it (z = its level):
/// contour lines, e.g. a Mandelbrot terrain's curves of equal escape time
/// (ft_mandelbrot_level_height). Free *out with ft_polylines_free.
FT_API ft_status ft_level_curves(const ft_heightfield* hf, const double* levels, size_t count,
                                 ft_polylines** out);

/// Parameters of Feder's clouds (seed 001): black below the threshold, above
/// it grey = ln(e / e_T) / ln(e_max / e_T), e = elevation above the lowest sample.
typedef struct ft_clouds_params {
  uint32_t struct_size;          ///< sizeof(ft_clouds_params); set by _init
  double threshold;              ///< height, or quantile in [0, 1]; default 0.5
  int32_t threshold_is_quantile; ///< default 1 (threshold at the median)
  int32_t bit_depth;             ///< 8 (values 0..255) or 16 (0..65535); default 8
} ft_clouds_params;

FT_API ft_status ft_clouds_params_init(ft_clouds_params* p);
/// Writes width * height grey values (row 0 = heightfield row 0) into `dst`,
/// which holds `count` uint16 values (at least width * height).
FT_API ft_status ft_clouds(const ft_heightfield* hf, const ft_clouds_params* params, uint16_t* dst,
                           size_t count);
/// Writes the clouds as a grey PNG of params->bit_depth bits to `path`
/// (atomically: a failed write leaves an existing file untouched).
FT_API ft_status ft_clouds_write_png(const ft_heightfield* hf, const ft_clouds_params* params, const char* path);

#ifdef __cplusplus
}
#endif
#endif
