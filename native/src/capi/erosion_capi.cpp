// The C ABI of the erosion layer (fracterra/erosion.h).
#include <memory>
#include <string>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "erosion/drainage_stats.hpp"
#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "fracterra/fracterra.h"

using ft::capi::guarded;

namespace {

void to_c(const ft::erosion::ErosionConfig& c, ft_erosion_params* p) {
  *p = {};
  p->struct_size = sizeof(ft_erosion_params);
  p->fluvial_steps = c.fluvial.steps;
  p->fluvial_dt = c.fluvial.dt;
  p->erodibility = c.fluvial.k;
  p->area_exponent = c.fluvial.m;
  p->diffusion = c.fluvial.diffusion;
  p->uplift = c.fluvial.uplift;
  p->hydraulic_iterations = c.hydraulic.iterations;
  p->hydraulic_dt = c.hydraulic.dt;
  p->rain = c.hydraulic.rain;
  p->evaporation = c.hydraulic.evaporation;
  p->capacity = c.hydraulic.capacity;
  p->dissolve = c.hydraulic.dissolve;
  p->deposit = c.hydraulic.deposit;
  p->thermal_iterations = c.thermal.iterations;
  p->talus_degrees = c.thermal.talus_degrees;
  p->thermal_rate = c.thermal.rate;
  p->periodic = c.periodic;
  p->threads = c.threads;
}

ft::erosion::ErosionConfig from_c(const ft_erosion_params& p) {
  ft::check_struct_size(p.struct_size, sizeof(ft_erosion_params), "ft_erosion_params");
  ft::erosion::ErosionConfig c;
  c.fluvial = {p.fluvial_steps, p.fluvial_dt, p.erodibility, p.area_exponent, p.diffusion, p.uplift};
  c.hydraulic.iterations = p.hydraulic_iterations;
  c.hydraulic.dt = p.hydraulic_dt;
  c.hydraulic.rain = p.rain;
  c.hydraulic.evaporation = p.evaporation;
  c.hydraulic.capacity = p.capacity;
  c.hydraulic.dissolve = p.dissolve;
  c.hydraulic.deposit = p.deposit;
  c.thermal = {p.thermal_iterations, p.talus_degrees, p.thermal_rate};
  c.periodic = p.periodic != 0;
  c.threads = p.threads;
  c.progress = ft::Progress(p.progress, p.progress_user);
  return c;
}

}  // namespace

extern "C" {

FT_API ft_status ft_erosion_params_init(ft_erosion_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    to_c(ft::erosion::ErosionConfig{}, p);
  });
}

FT_API ft_status ft_erosion_preset(const char* name, ft_erosion_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("name", name);
    to_c(ft::erosion::erosion_preset(name), p);
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
    ft::erosion::ErosionConfig c = from_c(*p);
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
