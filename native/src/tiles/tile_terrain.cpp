// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/tile_terrain.hpp"

#include "core/error.hpp"
#include "erosion/erosion_params.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::tiles {

int map_index(const std::string& name) {
  std::string known;
  for (size_t k = 0; k < kMapNames.size(); ++k) {
    if (name == kMapNames[k]) return int(k);
    known += (k ? ", " : "") + std::string(kMapNames[k]);
  }
  invalid("no map '" + name + "' in a tile set; the maps are " + known);
}

TileTerrain TileTerrain::of(const ft_build_params& given, bool maps) {
  const ft_build_params b = upgraded(pipeline::build_param_table(), given);
  check_ranges(pipeline::build_param_table(), &b);
  check_not_null("terrain", b.terrain);
  TileTerrain t;
  t.terrain = upgraded(terrain::terrain_param_table(), *b.terrain);
  t.terrain.threads = b.threads;
  t.terrain.progress = nullptr, t.terrain.progress_user = nullptr;
  if (b.erosion) {
    t.has_erosion = true;
    t.erosion = upgraded(erosion::erosion_param_table(), *b.erosion);
    t.erosion.progress = nullptr, t.erosion.progress_user = nullptr;
  }
  t.preset = b.erosion_preset;
  t.maps = maps;
  return t;
}

TileTerrain TileTerrain::of(const ft_terrain_params& given) {
  TileTerrain t;
  t.terrain = upgraded(terrain::terrain_param_table(), given);
  return t;
}

ft_build_params TileTerrain::build() const {
  ft_build_params b = defaults_of<ft_build_params>(pipeline::build_param_table());
  b.terrain = &terrain;
  b.erosion = has_erosion ? &erosion : nullptr;
  b.erosion_preset = preset;
  b.threads = terrain.threads;
  return b;
}

Heightfield& map_of(erosion::ErosionMaps& m, int k) {
  Heightfield* all[] = {&m.drainage_area, &m.slope, &m.curvature, &m.water_depth, &m.eroded, &m.deposited};
  return *all[k];
}

Heightfield build_window(const TileTerrain& t, const terrain::Window& w, erosion::ErosionMaps* maps) {
  if (!t.built()) return terrain::generate_terrain_window(t.terrain, 0, w.x0, w.y0, w.width, w.height);
  return pipeline::build_terrain_window(t.build(), w.x0, w.y0, w.width, w.height, maps);
}

}  // namespace ft::tiles
