// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstddef>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "terrain/mandelbrot.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_terrain_params_init(ft_terrain_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::terrain::default_terrain_params();
  });
}

FT_API ft_status ft_terrain_generate(const ft_terrain_params* p, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("params", p);
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::terrain::generate_terrain(ft::upgraded(ft::terrain::terrain_param_table(), *p));
    *out = h.release();
  });
}

FT_API ft_status ft_terrain_extent(const ft_terrain_params* p, int32_t lod, int64_t* width, int64_t* height) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("width", width);
    ft::check_not_null("height", height);
    *width = *height = 0;
    ft::terrain::terrain_extent(ft::upgraded(ft::terrain::terrain_param_table(), *p), lod, width, height);
  });
}

FT_API ft_status ft_terrain_generate_window_lod(const ft_terrain_params* p, int32_t lod, int64_t x0, int64_t y0,
                                                int32_t width, int32_t height, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("params", p);
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::terrain::generate_terrain_window(ft::upgraded(ft::terrain::terrain_param_table(), *p), lod, x0, y0, width, height);
    *out = h.release();
  });
}

FT_API ft_status ft_terrain_generate_window(const ft_terrain_params* p, int64_t x0, int64_t y0, int32_t width,
                                            int32_t height, ft_heightfield** out) {
  return ft_terrain_generate_window_lod(p, 0, x0, y0, width, height, out);
}

FT_API ft_status ft_mandelbrot_level_height(const ft_terrain_params* p, double iterations, double* height) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("height", height);
    *height = 0.0;
    ft::check_positive("sigma", p->sigma);
    ft::check_finite("iterations", iterations);
    *height = ft::terrain::mandelbrot_height(iterations, p->sigma);
  });
}

FT_API int32_t ft_terrain_side(int32_t levels) {
  return levels >= 1 && levels <= ft::terrain::kMaxLevels ? (1 << levels) + 1 : -1;
}

FT_API ft_status ft_profile_params_init(ft_profile_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::terrain::default_profile_params();
  });
}

FT_API ft_status ft_profile_generate(const ft_profile_params* p, float* dst, size_t count) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::terrain::generate_profile(ft::upgraded(ft::terrain::profile_param_table(), *p), dst, count);
  });
}

FT_API int64_t ft_profile_length(int32_t levels) {
  return levels >= 1 && levels <= ft::terrain::kMaxProfileLevels ? (int64_t(1) << levels) + 1 : -1;
}

}  // extern "C"
