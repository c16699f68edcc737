// SPDX-License-Identifier: GPL-3.0-or-later
// A tile set (fracterra tiles, 16-bit PNG tiles) as POV-Ray height_fields
// placed edge to edge: each tile's PNG spans its own samples, neighbours
// share their edge samples and one height scale, so the shared edges of
// neighbouring height_fields are the same points and the surface has no
// cracks. POV-Ray reads the PNGs where they are; nothing is rewritten.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ft::pov {

struct TiledTerrain {
  struct Tile {
    std::string png;            // path of the tile's PNG
    int64_t x0 = 0, y0 = 0;     // its first sample in the whole
    int32_t width = 0, height = 0;
  };
  std::vector<Tile> tiles;
  double spacing = 1;                     // world units between samples
  double height_min = 0, height_max = 1;  // the common 16-bit range, real units
};

// `union { height_field {...} ... }` of every tile, heights times
// vertical_scale, PNG paths relative to `folder` (the scene's), with
// water_level where `water_z` (world height; NaN for none) hides the bottom.
std::string tiled_terrain_sdl(const TiledTerrain& t, double vertical_scale, const std::string& folder, double water_z);

}  // namespace ft::pov
