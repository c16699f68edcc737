#include <memory>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "io/heightfield_io.hpp"
#include "refine/dem_refine.hpp"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_heightfield_read(const char* path, int32_t nodata, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("path", path);
    ft::check_int_range("nodata", nodata, FT_NODATA_REFUSE, FT_NODATA_KEEP);
    const ft::NodataPolicy policy = nodata == FT_NODATA_FILL   ? ft::NodataPolicy::fill
                                    : nodata == FT_NODATA_KEEP ? ft::NodataPolicy::keep
                                                               : ft::NodataPolicy::refuse;
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::read_heightfield(path, policy);
    *out = h.release();
  });
}

FT_API ft_status ft_heightfield_write(const ft_heightfield* hf, const char* path) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::check_not_null("path", path);
    ft::write_heightfield(hf->hf, path);
  });
}

FT_API void ft_dem_refine_params_init(ft_dem_refine_params* p) {
  if (!p) return;
  const ft::DemRefineConfig c;
  *p = ft_dem_refine_params{};
  p->struct_size = sizeof(ft_dem_refine_params);
  p->levels_added = c.levels_added;
  p->hurst = c.hurst;
  p->sigma = c.sigma;
  p->seed = c.seed;
  p->method = FT_TERRAIN_MIDPOINT;
  p->window_x = c.window_x;
  p->window_y = c.window_y;
  p->window_side = c.window_side;
  p->threads = c.threads;
}

FT_API ft_status ft_dem_refine(const ft_heightfield* dem, const ft_dem_refine_params* p, ft_heightfield** out,
                               ft_dem_refine_report* report) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("dem", dem);
    ft::check_not_null("params", p);
    ft::check_struct_size(p->struct_size, sizeof(ft_dem_refine_params), "ft_dem_refine_params");
    if (report) ft::check_struct_size(report->struct_size, sizeof(ft_dem_refine_report), "ft_dem_refine_report");
    if (p->method != FT_TERRAIN_MIDPOINT && p->method != FT_TERRAIN_ADDITIONS)
      ft::invalid("method must be FT_TERRAIN_MIDPOINT or FT_TERRAIN_ADDITIONS, got " + std::to_string(p->method));
    ft::check_int_range("threads", p->threads, 0, 1024);
    ft::DemRefineConfig c;
    c.levels_added = p->levels_added;
    c.hurst = p->hurst;
    c.sigma = p->sigma;
    c.seed = p->seed;
    c.additions = p->method == FT_TERRAIN_ADDITIONS;
    c.window_x = p->window_x;
    c.window_y = p->window_y;
    c.window_side = p->window_side;
    c.threads = p->threads;
    c.progress = p->progress;
    c.progress_user = p->progress_user;
    ft::DemRefineResult r = ft::refine_dem(dem->hf, c);
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
