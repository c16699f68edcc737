#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/clouds.hpp"
#include "analysis/hurst.hpp"
#include "analysis/quantile.hpp"
#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "contour/marching_squares.hpp"
#include "fracterra/fracterra.h"
#include "io/png_image.hpp"

using ft::capi::guarded;

namespace {

ft_hurst_params default_hurst_params() {
  ft_hurst_params p{};
  p.struct_size = sizeof(ft_hurst_params);
  p.method = FT_HURST_VARIOGRAM_ALIGNED;
  return p;
}

ft::HurstOptions to_options(const ft_hurst_params* params) {
  const ft_hurst_params p = params ? *params : default_hurst_params();
  ft::check_struct_size(p.struct_size, sizeof(ft_hurst_params), "ft_hurst_params");
  ft::check_int_range("method", p.method, FT_HURST_VARIOGRAM, FT_HURST_SPECTRAL);
  for (double v : {p.lag_min, p.lag_max, p.freq_min, p.freq_max}) ft::check_finite("band limit", v);
  ft::HurstOptions o;
  o.method = ft::HurstMethod(p.method);
  o.lag_min = p.lag_min, o.lag_max = p.lag_max, o.freq_min = p.freq_min, o.freq_max = p.freq_max;
  o.transects = p.transects != 0;
  return o;
}

void to_result(const ft::HurstEstimate& e, ft_hurst_result* out) {
  *out = ft_hurst_result{};
  out->method = int32_t(e.method);
  out->transects = e.transects;
  out->hurst = e.hurst;
  out->dimension = e.dimension;
  out->stderr_hurst = e.stderr_hurst;
  out->band_lo = e.band_lo;
  out->band_hi = e.band_hi;
  out->band_is_frequency = !ft::hurst_method_uses_lags(e.method);
  out->points = e.fit.points;
}

ft_clouds_params default_clouds_params() {
  ft_clouds_params p{};
  p.struct_size = sizeof(ft_clouds_params);
  p.threshold = 0.5;
  p.threshold_is_quantile = 1;
  p.bit_depth = 8;
  return p;
}

ft::CloudOptions to_cloud_options(const ft_clouds_params* params) {
  const ft_clouds_params p = params ? *params : default_clouds_params();
  if (p.struct_size < sizeof(ft_clouds_params))
    ft::invalid("ft_clouds_params.struct_size is " + std::to_string(p.struct_size) + ", expected " +
                std::to_string(sizeof(ft_clouds_params)) + " (call ft_clouds_params_init first)");
  ft::check_finite("threshold", p.threshold);
  ft::CloudOptions o;
  o.threshold = {p.threshold, p.threshold_is_quantile != 0};
  if (o.threshold.quantile) ft::check_range("threshold (a quantile)", p.threshold, 0.0, 1.0);
  o.bit_depth = p.bit_depth;
  return o;
}

}  // namespace

extern "C" {

FT_API ft_status ft_hurst_params_init(ft_hurst_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = default_hurst_params();
  });
}

FT_API ft_status ft_hurst_profile(const float* samples, size_t count, const ft_hurst_params* params,
                                  ft_hurst_result* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    ft::check_not_null("samples", samples);
    to_result(ft::estimate_hurst_profile(samples, count, to_options(params)), out);
  });
}

FT_API ft_status ft_hurst_heightfield(const ft_heightfield* hf, const ft_hurst_params* params,
                                      ft_hurst_result* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    ft::check_not_null("heightfield", hf);
    to_result(ft::estimate_hurst_surface(hf->hf, to_options(params)), out);
  });
}

FT_API ft_status ft_coastline(const ft_heightfield* hf, double level, int32_t level_is_quantile,
                              ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("heightfield", hf);
    ft::check_finite("level", level);
    ft::LevelSpec spec{level, level_is_quantile != 0};
    if (spec.quantile) ft::check_range("level (a quantile)", level, 0.0, 1.0);
    auto p = std::make_unique<ft_polylines>();
    p->set = ft::marching_squares(hf->hf, ft::resolve_level(hf->hf, spec));
    *out = p.release();
  });
}

FT_API ft_status ft_level_curves(const ft_heightfield* hf, const double* levels, size_t count,
                                 ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("levels", levels);
    ft::check_int_range("count (of levels)", int64_t(std::min<size_t>(count, 1u << 20)), 1, 4096);
    std::vector<double> v(levels, levels + count);
    for (size_t i = 0; i < count; ++i)
      if (!std::isfinite(v[i])) ft::invalid("levels[" + std::to_string(i) + "] must be finite, got " + ft::format_number(v[i]));
    auto p = std::make_unique<ft_polylines>();
    p->set = ft::marching_squares(hf->hf, v);
    *out = p.release();
  });
}

FT_API ft_status ft_clouds_params_init(ft_clouds_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = default_clouds_params();
  });
}

FT_API ft_status ft_clouds(const ft_heightfield* hf, const ft_clouds_params* params, uint16_t* dst, size_t count) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("dst", dst);
    if (count < hf->hf.size())
      ft::invalid("dst holds " + std::to_string(count) + " values, the clouds need width * height = " +
                  std::to_string(hf->hf.size()));
    const ft::GrayImage img = ft::clouds_image(hf->hf, to_cloud_options(params));
    std::copy(img.pixels.begin(), img.pixels.end(), dst);
  });
}

FT_API ft_status ft_clouds_write_png(const ft_heightfield* hf, const ft_clouds_params* params, const char* path) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("path", path);
    ft::write_png(path, ft::clouds_image(hf->hf, to_cloud_options(params)));
  });
}

}  // extern "C"
