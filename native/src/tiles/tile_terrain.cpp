#include "tiles/tile_terrain.hpp"

#include <cstring>

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

namespace {

Heightfield crop(const Heightfield& whole, const terrain::Window& w, double spacing) {
  Heightfield out(w.width, w.height);
  for (int32_t j = 0; j < w.height; ++j)
    std::memcpy(out.data() + size_t(j) * size_t(w.width),
                whole.data() + size_t(w.y0 + j) * size_t(whole.width()) + size_t(w.x0), sizeof(float) * size_t(w.width));
  out.set_world_size(spacing * double(w.width - 1));
  return out;
}

}  // namespace

Heightfield build_window(const TileTerrain& t, const terrain::Window& w, erosion::ErosionMaps* maps) {
  if (!t.built()) return terrain::generate_terrain_window(t.terrain, 0, w.x0, w.y0, w.width, w.height);
  // Until the pipeline's windows are bounded: the whole, cropped.
  const ft_build_params b = t.build();
  erosion::ErosionMaps whole_maps;
  const Heightfield whole = pipeline::build_terrain(b, maps ? &whole_maps : nullptr);
  if (w.x0 < 0 || w.y0 < 0 || w.width < 1 || w.height < 1 || w.x0 + w.width > whole.width() ||
      w.y0 + w.height > whole.height())
    invalid("the window is outside the terrain");
  const double spacing = whole.world_size() / double(whole.width() - 1);
  if (maps)
    for (int k = 0; k < FT_MAP_COUNT; ++k) map_of(*maps, k) = crop(map_of(whole_maps, k), w, spacing);
  return crop(whole, w, spacing);
}

}  // namespace ft::tiles
