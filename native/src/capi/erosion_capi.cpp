// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI of the erosion layer (fracterra/erosion.h).
#include <memory>
#include <string>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "erosion/drainage_stats.hpp"
#include "erosion/erosion.hpp"
#include "erosion/erosion_params.hpp"
#include "erosion/presets.hpp"
#include "fracterra/fracterra.h"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_erosion_params_init(ft_erosion_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_erosion_params>(ft::erosion::erosion_param_table());
  });
}

FT_API ft_status ft_erosion_preset(const char* name, ft_erosion_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("name", name);
    *p = ft::erosion::to_c(ft::erosion::erosion_preset(name));
  });
}

FT_API ft_status ft_erosion_preset_fitted(const char* name, const ft_heightfield* terrain, ft_erosion_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("name", name);
    ft::check_not_null("terrain", terrain);
    *p = ft::erosion::to_c(ft::erosion::erosion_preset(name, terrain->hf));
  });
}

FT_API ft_status ft_erode(const ft_heightfield* in, const ft_erosion_params* p, ft_heightfield** out,
                          ft_heightfield** maps) {
  return guarded([&] {
    ft::capi::reset_out(out);
    if (maps)
      for (int k = 0; k < FT_MAP_COUNT; ++k) maps[k] = nullptr;
    ft::check_not_null("in", in);
    ft::check_not_null("params", p);
    ft::erosion::ErosionConfig c = ft::erosion::from_c(*p);
    ft::erosion::ErosionMaps m;
    auto result = std::make_unique<ft_heightfield>();
    result->hf = ft::erosion::erode(in->hf, c, maps ? &m : nullptr);
    if (maps) {
      ft::Heightfield* all[FT_MAP_COUNT] = {&m.drainage_area, &m.slope, &m.curvature,
                                            &m.water_depth,   &m.eroded, &m.deposited};
      std::unique_ptr<ft_heightfield> made[FT_MAP_COUNT];
      for (int k = 0; k < FT_MAP_COUNT; ++k) {
        made[k] = std::make_unique<ft_heightfield>();
        made[k]->hf = std::move(*all[k]);
      }
      for (int k = 0; k < FT_MAP_COUNT; ++k) maps[k] = made[k].release();
    }
    *out = result.release();
  });
}

FT_API ft_status ft_drainage_statistics(const ft_heightfield* hf, int32_t periodic, double min_area_cells,
                                        ft_drainage_stats* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    *out = {};
    ft::check_not_null("hf", hf);
    const auto s = ft::erosion::drainage_stats(hf->hf, periodic != 0, min_area_cells);
    *out = {s.hack_h, s.hack_h_stderr, s.theta, s.theta_stderr, s.hack_bins, s.theta_bins};
  });
}

}  // extern "C"
