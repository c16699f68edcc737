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

}  // namespace ft::test
