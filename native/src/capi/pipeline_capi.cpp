// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI of the terrain pipeline (fracterra/pipeline.h).
#include <cmath>
#include <memory>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_build_params_init(ft_build_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_build_params>(ft::pipeline::build_param_table());
  });
}

namespace {

// Every output NULL (a failure leaves them so).
void reset_outputs(ft_heightfield** out, ft_heightfield** maps, ft_river_network** rivers) {
  ft::capi::reset_out(out);
  if (rivers) *rivers = nullptr;
  if (maps)
    for (int k = 0; k < FT_MAP_COUNT; ++k) maps[k] = nullptr;
}

// The maps into new handles, every one made before any is handed out.
void hand_out_maps(ft::erosion::ErosionMaps& m, ft_heightfield** maps) {
  if (!maps) return;
  std::unique_ptr<ft_heightfield> made[FT_MAP_COUNT];
  ft::Heightfield* all[FT_MAP_COUNT] = {&m.drainage_area, &m.slope, &m.curvature, &m.water_depth, &m.eroded, &m.deposited};
  for (int k = 0; k < FT_MAP_COUNT; ++k) {
    made[k] = std::make_unique<ft_heightfield>();
    made[k]->hf = std::move(*all[k]);
  }
  for (int k = 0; k < FT_MAP_COUNT; ++k) maps[k] = made[k].release();
}

}  // namespace

FT_API ft_status ft_terrain_build_rivers(const ft_build_params* p, ft_heightfield** out, ft_heightfield** maps,
                                         ft_river_network** rivers) {
  return guarded([&] {
    reset_outputs(out, maps, rivers);
    ft::check_not_null("params", p);
    ft::erosion::ErosionMaps m;
    auto result = std::make_unique<ft_heightfield>();
    auto network = rivers ? std::make_unique<ft_river_network>() : nullptr;
    result->hf = ft::pipeline::build_terrain(*p, maps ? &m : nullptr, network ? &network->net : nullptr);
    hand_out_maps(m, maps);
    if (rivers) *rivers = network.release();
    *out = result.release();
  });
}

FT_API ft_status ft_terrain_build_window(const ft_build_params* p, int64_t x0, int64_t y0, int32_t width,
                                         int32_t height, ft_heightfield** out, ft_heightfield** maps) {
  return guarded([&] {
    reset_outputs(out, maps, nullptr);
    ft::check_not_null("params", p);
    ft::erosion::ErosionMaps m;
    auto result = std::make_unique<ft_heightfield>();
    result->hf = ft::pipeline::build_terrain_window(*p, x0, y0, width, height, maps ? &m : nullptr);
    hand_out_maps(m, maps);
    *out = result.release();
  });
}

FT_API ft_status ft_terrain_build(const ft_build_params* p, ft_heightfield** out, ft_heightfield** maps) {
  return ft_terrain_build_rivers(p, out, maps, nullptr);
}

FT_API ft_status ft_terrain_world_init(ft_terrain_world* w) {
  return guarded([&] {
    ft::check_not_null("world", w);
    *w = ft_terrain_world{sizeof(ft_terrain_world), -1, NAN};
  });
}

FT_API ft_status ft_terrain_build_world(const ft_build_params* p, ft_heightfield** out, ft_heightfield** maps,
                                        ft_river_network** rivers, ft_terrain_world* world) {
  return guarded([&] {
    reset_outputs(out, maps, rivers);
    ft::check_not_null("params", p);
    ft::check_not_null("world", world);
    ft::erosion::ErosionMaps m;
    auto result = std::make_unique<ft_heightfield>();
    auto network = rivers ? std::make_unique<ft_river_network>() : nullptr;
    ft_terrain_world w{};
    result->hf = ft::pipeline::build_terrain(*p, maps ? &m : nullptr, network ? &network->net : nullptr, &w);
    hand_out_maps(m, maps);
    if (rivers) *rivers = network.release();
    *world = w;
    *out = result.release();
  });
}

FT_API ft_status ft_terrain_erode(const ft_build_params* p, const ft_heightfield* terrain,
                                  const ft_terrain_world* world, ft_heightfield** out, ft_heightfield** maps) {
  return guarded([&] {
    reset_outputs(out, maps, nullptr);
    ft::check_not_null("params", p);
    ft::check_not_null("terrain", terrain);
    ft::erosion::ErosionMaps m;
    auto result = std::make_unique<ft_heightfield>();
    result->hf = ft::pipeline::erode_made(*p, terrain->hf, world, maps ? &m : nullptr);
    hand_out_maps(m, maps);
    *out = result.release();
  });
}

FT_API ft_status ft_terrain_rivers(const ft_build_params* p, const ft_heightfield* terrain,
                                   const ft_terrain_world* world, ft_river_network** rivers) {
  return guarded([&] {
    ft::check_not_null("rivers", rivers);
    *rivers = nullptr;
    ft::check_not_null("params", p);
    ft::check_not_null("terrain", terrain);
    auto network = std::make_unique<ft_river_network>();
    network->net = ft::pipeline::rivers_made(*p, terrain->hf, world);
    *rivers = network.release();
  });
}

}  // extern "C"
