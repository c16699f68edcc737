// SPDX-License-Identifier: GPL-3.0-or-later
#include <memory>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "io/heightfield_io.hpp"
#include "refine/dem_refine.hpp"
#include "refine/dem_refine_params.hpp"

using ft::capi::guarded;

static_assert(ft::refine::kRefineMidpoint == FT_TERRAIN_MIDPOINT && ft::refine::kRefineAdditions == FT_TERRAIN_ADDITIONS,
              "ft_dem_refine_params.method takes the terrain's method values");

extern "C" {

FT_API ft_status ft_heightfield_read(const char* path, int32_t nodata, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("path", path);
    ft::check_int_range("nodata", nodata, FT_NODATA_REFUSE, FT_NODATA_KEEP);
    const ft::io::NodataPolicy policy = nodata == FT_NODATA_FILL   ? ft::io::NodataPolicy::fill
                                    : nodata == FT_NODATA_KEEP ? ft::io::NodataPolicy::keep
                                                               : ft::io::NodataPolicy::refuse;
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::io::read_heightfield(path, policy);
    *out = h.release();
  });
}

FT_API ft_status ft_heightfield_write(const ft_heightfield* hf, const char* path) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("path", path);
    ft::io::write_heightfield(hf->hf, path);
  });
}

FT_API void ft_dem_refine_params_init(ft_dem_refine_params* p) {
  if (p) *p = ft::defaults_of<ft_dem_refine_params>(ft::refine::dem_refine_param_table());
}

FT_API ft_status ft_dem_refine(const ft_heightfield* dem, const ft_dem_refine_params* p, ft_heightfield** out,
                               ft_dem_refine_report* report) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("dem", dem);
    ft::check_not_null("params", p);
    if (report) ft::check_struct_size(report->struct_size, sizeof(ft_dem_refine_report), "ft_dem_refine_report");
    const ft::refine::DemRefineConfig c = ft::refine::dem_refine_config(ft::upgraded(ft::refine::dem_refine_param_table(), *p));
    ft::refine::DemRefineResult r = ft::refine::refine_dem(dem->hf, c);
    if (report) {
      report->window_x = r.window_x;
      report->window_y = r.window_y;
      report->window_side = r.window_side;
      report->hurst = r.hurst;
      report->hurst_stderr = r.hurst_measured ? r.estimate.std_error : 0.0;
      report->sigma = r.sigma;
      report->increment_variance = r.v1;
      report->hurst_measured = r.hurst_measured;
      report->sigma_measured = r.sigma_measured;
    }
    auto h = std::make_unique<ft_heightfield>();
    h->hf = std::move(r.terrain);
    *out = h.release();
  });
}

}  // extern "C"
