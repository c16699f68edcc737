// SPDX-License-Identifier: GPL-3.0-or-later
// What a tile set is a set of windows of: the terrain pipeline's settings
// (terrain, landform, erosion: ft_build_params) and whether the set also
// holds the terrain's maps. Each tile is a window of the built terrain,
// bit-identical to the same samples of the whole (generated windows:
// terrain/window.hpp; eroded ones: pipeline's windows), so a tile set of an
// eroded terrain has no seams, and any process can write any tile.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "core/heightfield.hpp"
#include "erosion/erosion.hpp"           // ErosionMaps
#include "pipeline/terrain_build.hpp"  // ft_build_params
#include "terrain/window.hpp"

namespace ft::tiles {

// The maps a tile set holds with --maps, in ft_erosion_map order (their file folders under maps/).
inline constexpr std::array<const char*, FT_MAP_COUNT> kMapNames = {"drainage_area", "slope",  "curvature",
                                                                    "water_depth",   "eroded", "deposited"};
// The index of map `name` in kMapNames; throws naming the maps for another name.
int map_index(const std::string& name);

struct TileTerrain {
  ft_terrain_params terrain{};  // upgraded to this library's size
  bool has_erosion = false;     // erosion settings given (else the preset's alone, or none)
  ft_erosion_params erosion{};  // when has_erosion (upgraded); its masks point at the caller's data
  int32_t preset = FT_EROSION_PRESET_NONE;
  bool maps = false;            // the set holds the maps (kMapNames) beside the heights

  // From the pipeline's settings (upgraded and range-checked; the terrain is
  // validated for windows by the tile grid). Threads are the build's.
  static TileTerrain of(const ft_build_params& b, bool maps);
  // A generated terrain alone (the tile sets before erosion).
  static TileTerrain of(const ft_terrain_params& t);

  bool erodes() const { return has_erosion || preset != FT_EROSION_PRESET_NONE; }
  // Whether a tile needs the pipeline (erosion or maps), not just the generator.
  bool built() const { return erodes() || maps; }
  // The pipeline's settings, pointing into *this (valid while it lives).
  ft_build_params build() const;
};

// The samples of window `w` of the built terrain, and, when `maps` is not
// null, its maps' same samples. Throws for a window outside the terrain.
Heightfield build_window(const TileTerrain& t, const terrain::Window& w, erosion::ErosionMaps* maps);

// The map `k` (kMapNames order) of `maps`.
Heightfield& map_of(erosion::ErosionMaps& maps, int k);

}  // namespace ft::tiles
