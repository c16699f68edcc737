// SPDX-License-Identifier: GPL-3.0-or-later
// A tile set on disk: a folder holding the tiles of one terrain, its
// manifest and its VRT mosaic (tile_grid.hpp, tile_writer.hpp, manifest.hpp,
// mosaic_vrt.hpp). TileSet is the driver's side: it opens or resumes the
// folder, says which tiles are still to do, records each finished tile's
// CRC-32 in the manifest, and finishes with the mosaic. The tiles themselves
// are written by write_tile, a pure function any process can run (the CLI
// in-process, Dask on workers).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "tiles/height_range.hpp"
#include "tiles/tile_terrain.hpp"
#include "tiles/tile_writer.hpp"

namespace ft::tiles {

class TileSet {
 public:
  // Validates `p` for windows, creates `dir` if needed and reads its
  // manifest: a folder that holds another tile set's manifest (other
  // parameters, tile size or format) is refused with the first difference. A
  // new set gets its height range (height_range.hpp) and its manifest at once;
  // a resumed one keeps the range in its manifest. With `defer_exact_pass`,
  // a new set whose range needs the exact pass over every tile is left
  // without one (range_pending()) and nothing is written until
  // set_height_range() gives it: a driver runs that pass elsewhere, one task
  // per tile (tile_height_range, Dask).
  TileSet(const TileTerrain& t, int64_t tile, TileFormat format, std::string dir, bool defer_exact_pass = false);
  // A generated terrain's set (no erosion, no maps).
  TileSet(const ft_terrain_params& p, int64_t tile, TileFormat format, std::string dir, bool defer_exact_pass = false)
      : TileSet(TileTerrain::of(p), tile, format, std::move(dir), defer_exact_pass) {}

  const TileSpec& spec() const noexcept { return spec_; }
  const std::string& dir() const noexcept { return dir_; }
  const nlohmann::json& manifest() const noexcept { return manifest_; }
  bool range_pending() const noexcept { return range_pending_; }
  // The exact range of a pending set (the union of its tiles' ranges):
  // writes the new manifest. Refused when the range is not pending or is
  // not finite and ordered.
  void set_height_range(double min, double max);
  // True when the tile's files (heights, and maps when the set has them)
  // exist and their CRC-32s are the ones recorded.
  bool done(int32_t col, int32_t row) const;
  // Records a written tile's CRC-32s in the manifest's journal (manifest.hpp).
  void record(int32_t col, int32_t row, const TileCrcs& crcs);
  void record(int32_t col, int32_t row, uint32_t heights_crc) { record(col, row, TileCrcs{heights_crc, {}}); }
  // Tiles with a recorded CRC-32.
  int64_t recorded() const;
  // Every tile recorded: writes the VRT mosaics (heights, and each map's:
  // maps/<map>.vrt, without overviews), removes the range pass's pending
  // folder and marks the manifest complete.
  void finish();

 private:
  nlohmann::json& entry(int32_t col, int32_t row);
  void check_range_fixed(const char* what) const;
  TileSpec spec_;
  std::string dir_;
  nlohmann::json identity_, manifest_;
  bool range_pending_ = false;
};

}  // namespace ft::tiles
