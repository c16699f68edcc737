// SPDX-License-Identifier: GPL-3.0-or-later
// Terrains as POV-Ray `height_field`s: a 16-bit grayscale PNG normalised to
// 0..1 plus an SDL object that restores real units with `scale`. A 1025^2
// grid parses in a tenth of a second this way; the same grid as mesh2 is
// ~70x larger and ~100x slower to parse, so fracterra never writes mesh2.
#pragma once

#include <string>

#include "core/heightfield.hpp"

namespace ft::pov {

// Where a heightfield sits in the world: columns span x in [0, world_size_x],
// rows span y in [0, world_size_y] (row 0 at y = 0), heights are samples times
// vertical_scale.
struct TerrainPlacement {
  double world_size_x = 1.0, world_size_y = 1.0, vertical_scale = 1.0;
  double z_min = 0.0, z_max = 0.0;  // real heights of the darkest and brightest pixel
  int32_t width = 0, height = 0;    // samples
};

// Checks world_size_x, world_size_y, vertical_scale and the grid (at least 2 x 2,
// finite samples); throws FT_ERR_INVALID_ARGUMENT naming what is wrong.
void validate_terrain(const Heightfield& hf, double world_size_x, double world_size_y, double vertical_scale);

// Writes `hf` atomically as the 16-bit PNG of io/heightfield_io (which also
// records the range in tEXt, so the file is an ordinary fracterra terrain)
// and returns its placement.
TerrainPlacement write_heightfield_png(const Heightfield& hf, const std::string& png_path,
                                       double world_size_x, double world_size_y, double vertical_scale);

// The placement of a terrain without writing anything (z range from the data).
TerrainPlacement place_terrain(const Heightfield& hf, double world_size_x, double world_size_y,
                               double vertical_scale);

// An SDL `height_field { ... }` for the PNG at `png_ref` (a path as the
// scene should spell it, usually relative), `smooth`, placed in POV axes so
// that world (x, y, z) lands at POV <x, z, y>. `water_z` (world height) adds
// `water_level` (POV-Ray's keyword) so POV-Ray skips what the sea hides; NaN for none.
// `modifiers` (trusted SDL, e.g. a texture) is appended inside the object.
std::string heightfield_sdl(const std::string& png_ref, const TerrainPlacement& place, double water_z,
                            const std::string& modifiers = "");

// The scale POV-Ray needs on y: it reads a 16-bit pixel v as v / 65536, we
// wrote (z - z_min) / (z_max - z_min) * 65535, so y must grow by 65536/65535
// for pixel heights to land exactly (the trace() probe test checks this).
double pov_height_scale(const TerrainPlacement& place);

}  // namespace ft::pov
