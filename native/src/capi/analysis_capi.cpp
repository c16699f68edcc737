// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>
#include <vector>

#include "analysis/analysis_params.hpp"
#include "analysis/clouds.hpp"
#include "analysis/hurst.hpp"
#include "analysis/hurst_choice.hpp"
#include "analysis/increment_sums.hpp"
#include "analysis/quantile.hpp"
#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "contour/marching_squares.hpp"
#include "fracterra/fracterra.h"
#include "io/png_image.hpp"

using ft::capi::guarded;

namespace {

// The caller's params over the table's defaults (NULL: the defaults), as the estimator's options.
ft::analysis::HurstOptions to_options(const ft_hurst_params* params, int64_t width, int64_t height,
                            std::optional<ft::analysis::HurstChoice>& choice) {
  const ft::ParamTable& t = ft::analysis::hurst_param_table();
  const ft_hurst_params p = params ? ft::upgraded(t, *params) : ft::defaults_of<ft_hurst_params>(t);
  return ft::analysis::hurst_options(p, width, height, choice);
}

void to_result(const ft::analysis::HurstEstimate& e, const std::optional<ft::analysis::HurstChoice>& choice, ft_hurst_result* out) {
  ft_hurst_result r{};
  r.method = int32_t(e.method);
  r.transects = e.transects;
  r.hurst = e.hurst;
  r.dimension = e.dimension;
  r.std_error = e.std_error;
  r.band_lo = e.band_lo;
  r.band_hi = e.band_hi;
  r.band_is_frequency = !ft::analysis::hurst_method_uses_lags(e.method);
  r.points = e.fit.points;
  r.auto_reason = choice ? int32_t(choice->reason) : FT_HURST_REASON_NONE;
  r.auto_reason_text = choice ? choice->why : "";
  ft::capi::write_result(out, r, sizeof(ft_hurst_result), "ft_hurst_result");
}

ft::analysis::CloudOptions to_cloud_options(const ft_clouds_params* params) {
  const ft::ParamTable& t = ft::analysis::clouds_param_table();
  return ft::analysis::cloud_options(params ? ft::upgraded(t, *params) : ft::defaults_of<ft_clouds_params>(t));
}

}  // namespace

extern "C" {

FT_API ft_status ft_hurst_params_init(ft_hurst_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_hurst_params>(ft::analysis::hurst_param_table());
  });
}

FT_API ft_status ft_hurst_profile(const float* samples, size_t count, const ft_hurst_params* params,
                                  ft_hurst_result* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    ft::check_not_null("samples", samples);
    std::optional<ft::analysis::HurstChoice> choice;
    const ft::analysis::HurstOptions o = to_options(params, int64_t(count), 1, choice);
    to_result(ft::analysis::estimate_hurst_profile(samples, count, o), choice, out);
  });
}

FT_API ft_status ft_hurst_heightfield(const ft_heightfield* hf, const ft_hurst_params* params,
                                      ft_hurst_result* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    ft::check_not_null("heightfield", hf);
    std::optional<ft::analysis::HurstChoice> choice;
    const ft::analysis::HurstOptions o = to_options(params, hf->hf.width(), hf->hf.height(), choice);
    to_result(ft::analysis::estimate_hurst_surface(hf->hf, o), choice, out);
  });
}

FT_API ft_status ft_hurst_heightfield_points(const ft_heightfield* hf, const ft_hurst_params* params,
                                             ft_hurst_result* out, double* x, double* y, int64_t capacity,
                                             int64_t* count) {
  return guarded([&] {
    ft::check_not_null("out", out);
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("count", count);
    std::optional<ft::analysis::HurstChoice> choice;
    const ft::analysis::HurstOptions o = to_options(params, hf->hf.width(), hf->hf.height(), choice);
    const ft::analysis::HurstEstimate e = ft::analysis::estimate_hurst_surface(hf->hf, o);
    *count = int64_t(e.x.size());
    if (capacity == 0 && !x && !y) return to_result(e, choice, out);
    ft::check_not_null("x", x);
    ft::check_not_null("y", y);
    if (capacity < int64_t(e.x.size()))
      ft::invalid("ft_hurst_heightfield_points: capacity " + std::to_string(capacity) + " is below the " +
                  std::to_string(e.x.size()) + " points fitted");
    std::copy(e.x.begin(), e.x.end(), x);
    std::copy(e.y.begin(), e.y.end(), y);
    to_result(e, choice, out);
  });
}

namespace {

// The options and lags of a whole surface for the window sums.
std::vector<int64_t> window_lags(const ft_hurst_params* params, int64_t w, int64_t h, ft::analysis::HurstOptions& o,
                                 std::optional<ft::analysis::HurstChoice>& choice) {
  o = to_options(params, w, h, choice);
  return ft::analysis::surface_lags(o, w, h);
}

void check_lag_count(size_t given, size_t wanted) {
  if (given != wanted)
    ft::invalid("count is " + std::to_string(given) + "; this surface and band have " + std::to_string(wanted) +
                " lags (ft_increment_lags)");
}

}  // namespace

FT_API ft_status ft_increment_lags(const ft_hurst_params* params, int64_t whole_width, int64_t whole_height,
                                   int64_t* lags, size_t capacity, size_t* count) {
  return guarded([&] {
    ft::check_not_null("count", count);
    *count = 0;
    ft::analysis::HurstOptions o;
    std::optional<ft::analysis::HurstChoice> choice;
    const std::vector<int64_t> l = window_lags(params, whole_width, whole_height, o, choice);
    if (capacity > 0) ft::check_not_null("lags", lags);
    std::copy_n(l.begin(), std::min(capacity, l.size()), lags);
    *count = l.size();
  });
}

FT_API ft_status ft_increment_sums(const ft_heightfield* window, const ft_hurst_params* params, int64_t x0,
                                   int64_t y0, int64_t whole_width, int64_t whole_height, double* sums,
                                   double* counts, size_t count) {
  return guarded([&] {
    ft::check_not_null("window", window);
    ft::check_not_null("sums", sums);
    ft::check_not_null("counts", counts);
    ft::analysis::HurstOptions o;
    std::optional<ft::analysis::HurstChoice> choice;
    const std::vector<int64_t> l = window_lags(params, whole_width, whole_height, o, choice);
    check_lag_count(count, l.size());
    ft::analysis::add_window_increments(window->hf, o.method, x0, y0, whole_width, whole_height, l, sums, counts);
  });
}

FT_API ft_status ft_hurst_from_increment_sums(const ft_hurst_params* params, int64_t whole_width,
                                              int64_t whole_height, const double* sums, const double* counts,
                                              size_t count, ft_hurst_result* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    ft::check_not_null("sums", sums);
    ft::check_not_null("counts", counts);
    ft::analysis::HurstOptions o;
    std::optional<ft::analysis::HurstChoice> choice;
    const std::vector<int64_t> l = window_lags(params, whole_width, whole_height, o, choice);
    check_lag_count(count, l.size());
    to_result(ft::analysis::estimate_from_increments(o.method, l, sums, counts), choice, out);
  });
}

FT_API ft_status ft_coastline(const ft_heightfield* hf, double level, int32_t level_is_quantile,
                              ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("heightfield", hf);
    ft::check_finite("level", level);
    ft::analysis::LevelSpec spec{level, level_is_quantile != 0};
    if (spec.quantile) ft::check_range("level (a quantile)", level, 0.0, 1.0);
    auto p = std::make_unique<ft_polylines>();
    p->set = ft::contour::marching_squares(hf->hf, ft::analysis::resolve_level(hf->hf, spec));
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
    p->set = ft::contour::marching_squares(hf->hf, v);
    *out = p.release();
  });
}

FT_API ft_status ft_clouds_params_init(ft_clouds_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_clouds_params>(ft::analysis::clouds_param_table());
  });
}

FT_API ft_status ft_clouds(const ft_heightfield* hf, const ft_clouds_params* params, uint16_t* dst, size_t count) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("dst", dst);
    if (count < hf->hf.size())
      ft::invalid("dst holds " + std::to_string(count) + " values, the clouds need width * height = " +
                  std::to_string(hf->hf.size()));
    const ft::GrayImage img = ft::analysis::clouds_image(hf->hf, to_cloud_options(params));
    std::copy(img.pixels.begin(), img.pixels.end(), dst);
  });
}

FT_API ft_status ft_clouds_write_png(const ft_heightfield* hf, const ft_clouds_params* params, const char* path) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("path", path);
    ft::io::write_png(path, ft::analysis::clouds_image(hf->hf, to_cloud_options(params)));
  });
}

}  // extern "C"
