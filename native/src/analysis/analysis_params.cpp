// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/analysis_params.hpp"

#include <cfloat>

#include "core/error.hpp"

namespace ft::analysis {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr double kInf = DBL_MAX;
// The increment methods read the lag band, the spectral one the frequency
// band; "auto" may pick either, so it reads both.
constexpr uint64_t kLags = method_bit(FT_HURST_VARIOGRAM) | method_bit(FT_HURST_MADOGRAM) |
                           method_bit(FT_HURST_VARIOGRAM_ALIGNED) | method_bit(FT_HURST_MADOGRAM_ALIGNED) |
                           method_bit(FT_HURST_AUTO);
constexpr uint64_t kFrequencies = method_bit(FT_HURST_SPECTRAL) | method_bit(FT_HURST_AUTO);

constexpr ft_param_enum_item kHurstMethods[] = {
    {FT_HURST_VARIOGRAM, "VARIOGRAM", "Variogram",
     "0.5 E[(X(t+tau) - X(t))^2] ~ tau^(2H), integer lags ~4 per octave"},
    {FT_HURST_MADOGRAM, "MADOGRAM", "Madogram", "E|X(t+tau) - X(t)| ~ tau^H (Gneiting et al. 2012)"},
    {FT_HURST_VARIOGRAM_ALIGNED, "VARIOGRAM_ALIGNED", "Aligned Variogram",
     "Variogram over dyadic-grid pairs only (tau = 2^j, t a multiple of tau): exact for midpoint displacement"},
    {FT_HURST_MADOGRAM_ALIGNED, "MADOGRAM_ALIGNED", "Aligned Madogram", "Madogram over dyadic-grid pairs only"},
    {FT_HURST_SPECTRAL, "SPECTRAL", "Spectral",
     "Power spectrum P(f) ~ f^-(2H + 1) (Voss 1988): detrended, Hann window, 8 log bins per octave"},
    {FT_HURST_AUTO, "AUTO", "Recommended",
     "The estimator recommended for the input: aligned variogram on 2^n + 1 samples per side, else spectral "
     "from 256 samples, else the variogram"},
};

#define ROW(field, type) FT_PARAM_ROW(ft_hurst_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kHurstRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_hurst_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_hurst_params), set by ft_hurst_params_init", .methods = kAll},
    {ROW(method, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_HURST_VARIOGRAM_ALIGNED, .hard_min = 0,
     .hard_max = FT_HURST_AUTO, .soft_min = 0, .soft_max = FT_HURST_AUTO, .unit = "", .label = "Estimator",
     .doc = "Hurst estimator: the slope of a log-log least-squares fit over a band", .methods = kAll,
     .enum_count = 6, .enum_items = kHurstMethods},
    {ROW(lag_min, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 64, .unit = "samples", .label = "Smallest Lag",
     .doc = "Smallest lag fitted; 0: 1", .methods = kLags},
    {ROW(lag_max, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 1024, .unit = "samples", .label = "Largest Lag",
     .doc = "Largest lag fitted; 0: max(2, (n - 1) / 16), n = the profile length or the shorter side",
     .methods = kLags},
    {ROW(freq_min, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 64, .unit = "cycles per record", .label = "Lowest Frequency",
     .doc = "Lowest frequency fitted; 0: clamp(n / 128, 1, 8)", .methods = kFrequencies},
    {ROW(freq_max, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 1024, .unit = "cycles per record", .label = "Highest Frequency",
     .doc = "Highest frequency fitted, at most n / 2; 0: n / 8", .methods = kFrequencies},
    {ROW(transects, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Transect Median",
     .doc = "Heightfields: the median of the estimates of every row and column instead of one pooled fit",
     .methods = kAll},
};
#undef ROW

#define ROW(field, type) FT_PARAM_ROW(ft_clouds_params, field, type)
constexpr ft_param_info kCloudsRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_clouds_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_clouds_params), set by ft_clouds_params_init", .methods = kAll},
    {ROW(threshold, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.5, .hard_min = -kInf, .hard_max = kInf,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Threshold",
     .doc = "Height below which the sky is black (Feder 1988, seed 001), or with threshold_is_quantile the "
            "fraction of samples below it, in [0, 1]",
     .methods = kAll},
    {ROW(threshold_is_quantile, FT_PARAM_BOOL), .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Threshold Is a Quantile",
     .doc = "The threshold is a quantile of the heights (0.5: the median), not a height", .methods = kAll},
    {ROW(bit_depth, FT_PARAM_INT32), .element_kind = -1, .default_value = 8, .hard_min = 8, .hard_max = 16,
     .soft_min = 8, .soft_max = 16, .unit = "bits", .label = "Bit Depth",
     .doc = "Bits per grey sample: 8 (0..255) or 16 (0..65535)", .methods = kAll},
};
#undef ROW
FT_PARAM_TABLE_END

}  // namespace

const ParamTable& hurst_param_table() {
  static const ParamTable table{"ft_hurst_params", sizeof(ft_hurst_params), kHurstRows};
  return table;
}

const ParamTable& clouds_param_table() {
  static const ParamTable table{"ft_clouds_params", sizeof(ft_clouds_params), kCloudsRows};
  return table;
}

HurstOptions hurst_options(const ft_hurst_params& p, int64_t width, int64_t height,
                           std::optional<HurstChoice>& choice) {
  check_ranges(hurst_param_table(), &p);  // the band against the record is the estimator's to check
  HurstOptions o;
  if (p.method == FT_HURST_AUTO) {
    choice = choose_hurst_method(width, height);
    o.method = choice->method;
  } else {
    o.method = HurstMethod(p.method);
  }
  o.lag_min = p.lag_min, o.lag_max = p.lag_max, o.freq_min = p.freq_min, o.freq_max = p.freq_max;
  o.transects = p.transects != 0;
  return o;
}

CloudOptions cloud_options(const ft_clouds_params& p) {
  check_ranges(clouds_param_table(), &p);
  CloudOptions o;
  o.threshold = {p.threshold, p.threshold_is_quantile != 0};
  // Cross-field: a quantile is a fraction (the bit depth, 8 or 16, is clouds_image's to check).
  if (o.threshold.quantile) check_range("threshold (a quantile)", p.threshold, 0.0, 1.0);
  o.bit_depth = p.bit_depth;
  return o;
}

}  // namespace ft::analysis
