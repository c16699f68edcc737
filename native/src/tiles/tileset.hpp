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

#include "terrain/terrain.hpp"  // ft_terrain_params
#include "tiles/height_range.hpp"
#include "tiles/tile_writer.hpp"

namespace ft {

class TileSet {
 public:
  // Validates `p` for windows, creates `dir` if needed and reads its
  // manifest: a folder that holds another tile set's manifest (other
  // parameters, tile size or format) is refused with the first difference. A
  // new set gets its height range (height_range.hpp) and its manifest at once;
  // a resumed one keeps the range in its manifest.
  TileSet(const ft_terrain_params& p, int64_t tile, TileFormat format, std::string dir);

  const TileSpec& spec() const noexcept { return spec_; }
  const std::string& dir() const noexcept { return dir_; }
  const nlohmann::json& manifest() const noexcept { return manifest_; }
  // True when the tile's file exists and its CRC-32 is the one recorded.
  bool done(int32_t col, int32_t row) const;
  // Records a written tile's CRC-32 and rewrites the manifest.
  void record(int32_t col, int32_t row, uint32_t crc);
  // Tiles with a recorded CRC-32.
  int64_t recorded() const;
  // Every tile recorded: writes the VRT mosaic and marks the manifest complete.
  void finish();

 private:
  nlohmann::json& entry(int32_t col, int32_t row);
  TileSpec spec_;
  std::string dir_;
  nlohmann::json manifest_;
};

}  // namespace ft
