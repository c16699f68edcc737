// SPDX-License-Identifier: GPL-3.0-or-later
// A finished tile set (tiles/) cut again the way a game engine imports a
// large terrain in pieces, with one sidecar for the whole:
//   Unity:  tiles of 2^n + 1 samples that share their edge samples, as
//           neighbouring Unity terrains do; RAW16 little-endian on the set's
//           common height scale; named NAME_X_Z.raw (Terrain Tools' batch
//           import reads the X and Z indices from the name).
//   Unreal: tiles of N samples that do not overlap (the landscape importer
//           lays tile (x, y) at x N, y N); 16-bit PNG on the common scale;
//           named NAME_x<X>_y<Y>.png, as its tiled import expects.
//   Godot:  Terrain3D regions of --region-size samples that do not overlap,
//           float EXR heights in metres, NAME_x<X>_y<Y>.exr, each with its
//           position in the sidecar.
// The tiles are read back from the set (tiles::read_tileset_window), so the
// terrain is generated once; 16-bit engine tiles of a png16 set hold exactly
// the set's codes. Tile (X, Y) covers the whole's samples from (X step,
// Y step), step = N - 1 for Unity and N for the others: a set of side W
// needs (W - 1) divisible by the step (the last sample row and column are
// then left out by Unreal and Godot, whose tiles do not share them).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "engines/engine_export.hpp"

namespace ft::engines {

// The engine tile's samples per side for a set of width x height samples:
// o.side when given (it must cut the set); else the size whose tiles start
// `preferred_step` apart (the set's own tiles) when it cuts the set; else
// the largest size that does (at most Unity 1025, Unreal 1024, Godot the
// region size). Throws naming the sizes that would do.
int32_t engine_tile_side(const EngineOptions& o, int64_t width, int64_t height, int64_t preferred_step = 0);

// Writes the engine's tiles of the finished set in `set_dir` into `out_dir`
// (created), and `out_dir/<engine>.json` with the grid, the files, each
// tile's position and the numbers for the importer. The tile size is
// engine_tile_side's, with the set's tiles as the preferred step; refused
// before anything is written. Returns the sidecar.
nlohmann::json write_engine_tiles(const std::string& set_dir, const std::string& out_dir, const EngineOptions& o,
                                  const std::string& name = "terrain");

}  // namespace ft::engines
