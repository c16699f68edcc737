// SPDX-License-Identifier: GPL-3.0-or-later
// Terrains several native test files start from, written once.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "terrain/terrain.hpp"

namespace ft::test {

// An fBm terrain (H 0.8), 10 world units across; spectral synthesis of the
// same spectrum when `periodic` (so it tiles and erodes as a torus).
inline Heightfield fbm_terrain(int32_t size, uint64_t seed, bool periodic = false) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = periodic ? FT_TERRAIN_SPECTRAL : FT_TERRAIN_FBM;
  p.width = p.height = size;
  p.seed = seed;
  p.hurst = 0.8;
  Heightfield hf = terrain::generate_terrain(p);
  hf.set_world_size(10.0);
  return hf;
}

// The add-on's default terrain (blender_addon/fracterra/core/params.py's
// BLENDER_OVERRIDES): a midpoint mountain, levelled, raised and faded out
// radially, 10 world units across.
inline Heightfield default_mountain(int32_t levels, uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = FT_TERRAIN_MIDPOINT;
  p.levels = levels;
  p.width = p.height = (1 << levels) + 1;
  p.seed = seed;
  p.sigma = 2.0;
  p.levelling = 1.0;
  p.height_offset = 1.5;
  p.falloff = FT_FALLOFF_RADIAL;
  p.falloff_width = 0.9;
  p.world_size = 10.0;
  Heightfield hf = terrain::generate_terrain(p);
  hf.set_world_size(10.0);
  return hf;
}

}  // namespace ft::test
