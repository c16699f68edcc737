// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/tiled_terrain.hpp"

#include "core/error.hpp"
#include "povray/heightfield_export.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov {

std::string tiled_terrain_sdl(const TiledTerrain& t, double vertical_scale, const std::string& folder, double water_z) {
  if (t.tiles.empty()) invalid("the tile set has no tiles");
  check_positive("tile spacing", t.spacing);
  check_positive("vertical_scale", vertical_scale);
  std::string s = "union {\n";
  for (const TiledTerrain::Tile& tile : t.tiles) {
    if (tile.width < 2 || tile.height < 2) invalid("a tile of " + tile.png + " has fewer than 2 x 2 samples");
    TerrainPlacement place;
    place.world_size_x = t.spacing * (tile.width - 1);
    place.world_size_y = t.spacing * (tile.height - 1);
    place.vertical_scale = vertical_scale;
    place.z_min = t.height_min * vertical_scale;
    place.z_max = t.height_max * vertical_scale;
    place.width = tile.width;
    place.height = tile.height;
    s += heightfield_sdl(relative_path(tile.png, folder), place, water_z,
                         "  translate " + vec({t.spacing * double(tile.x0), 0, t.spacing * double(tile.y0)}) + "\n");
  }
  s += "}\n";
  return s;
}

}  // namespace ft::pov
