// SPDX-License-Identifier: GPL-3.0-or-later
// A heightfield written the way a game engine's importer takes it (see
// engine_preset.hpp): resampled to the engine's size, in its format, with a
// sidecar "<out>.json" holding the numbers for the import dialog.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/heightfield.hpp"
#include "engines/engine_preset.hpp"
#include "splat/splat_map.hpp"

namespace ft::engines {

struct EngineOptions {
  Engine engine = Engine::unity;
  int32_t region_size = kGodotDefaultRegion;  // Godot (Terrain3D)
  int32_t side = 0;                           // samples per side; 0: the engine's size nearest the terrain's
};

// The output's extension each engine takes (".raw", ".png", ".exr").
const char* engine_extension(Engine e);

// Bilinear, corner to corner: the first and last samples stay where they
// are, so the world extent does not change.
Heightfield resample(const Heightfield& hf, int32_t width, int32_t height);

// The width x height the engine takes for `hf` (Unity and Unreal: square;
// Godot: each side a multiple of the region size). Throws for a terrain the
// engine cannot take (Unity or Unreal and not square).
std::pair<int32_t, int32_t> engine_size(const Heightfield& hf, const EngineOptions& o);

// Refuses, before any work, a region size, side or extension the engine does not take.
void check_engine_output(const EngineOptions& o, const std::string& out);

// The Terrain3D control map of `hf`: at each sample the two layers with the
// largest weights (default splat rules over `maps`, whose terrain is `hf`'s
// and whose maps may be null) as base and overlay, and the overlay's share of
// the two as the blend.
Heightfield control_map(const Heightfield& hf, const splat::SplatInputs& maps);

// Writes `hf` (and for Godot its control map, by the default splat rules
// over `maps`, which may hold null maps) to `out`, whose extension must be
// the engine's. Returns the sidecar (also written to out + ".json").
nlohmann::json write_for_engine(const Heightfield& hf, const std::string& out, const EngineOptions& o,
                                const splat::SplatInputs& maps = {});

}  // namespace ft::engines
