// SPDX-License-Identifier: GPL-3.0-or-later
// One tile of a tile set, written as a pure function of the terrain's
// parameters, the tile grid, the format and the common height range: the
// same inputs give the same bytes in any process on any machine, so a task
// that writes a tile can be retried or resumed safely (Dask, the CLI).
//
//   png16: 16-bit grayscale, (z - min) 65535 / (max - min) rounded, the same
//          range for every tile (so shared edges agree exactly), recorded in
//          the tEXt chunks fracterra:min / fracterra:max as for any fracterra
//          PNG; a world file (.pgw) beside it places it in the mosaic;
//   tiff:  Cloud-Optimized GeoTIFF float32 (exact heights), georeferenced.
//
// A set with maps holds beside each tile its maps' same samples, as float32
// GeoTIFFs maps/<map>/tile_rRRR_cCCC.tif (tile_terrain.hpp's kMapNames).
//
// An eroded set's height range is exact (the union of its tiles'), so each
// tile is built once for the range and written after it: the range pass
// keeps what it built in a folder of the set, .pending-<identity CRC>/
// (heights as .npy, maps as their final GeoTIFFs), which the writing pass
// takes instead of building the tile again; a tile not kept there is built.
// Either way the same bytes.
//
// Map coordinates: sample (x, y) of the whole terrain is at
// (x s, -y s), s = world_size / (width - 1) the sample spacing, north up.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/heightfield.hpp"
#include "terrain/terrain.hpp"  // ft_terrain_params
#include "tiles/tile_grid.hpp"
#include "tiles/tile_terrain.hpp"

namespace ft::tiles {

enum class TileFormat { png16 = 0, tiff = 1 };

struct TileSpec {
  TileGrid grid;
  TileFormat format = TileFormat::png16;
  double height_min = 0, height_max = 1;  // the common scale of 16-bit tiles
  double spacing = 1;                      // world units between neighbouring samples
  bool maps = false;                       // the set holds the maps too
  std::string pending;                     // the range pass's folder in the set (.pending-XXXXXXXX)
};

// The spec of terrain `t` cut into tiles of `tile` cells (validates the
// terrain for windows: spectral and out-of-range sizes are refused there;
// maps need GDAL, for their GeoTIFFs).
TileSpec make_tile_spec(const TileTerrain& t, int64_t tile, TileFormat format, double height_min = 0,
                        double height_max = 1);

const char* format_name(TileFormat f);     // "png16", "tiff"
TileFormat parse_tile_format(const std::string& name);  // throws naming the choices
// "tile_r003_c012.png": zero-padded to the grid's digits.
std::string tile_file_name(const TileSpec& spec, int32_t col, int32_t row);
// "maps/deposited/tile_r003_c012.tif": map k's tile (kMapNames order).
std::string map_file_name(const TileSpec& spec, int k, int32_t col, int32_t row);
// GDAL's geotransform of tile (col, row) (pixel-is-area: its top-left corner
// is half a spacing up and left of its first sample).
void tile_geotransform(const TileSpec& spec, int32_t col, int32_t row, double transform[6]);

// The CRC-32s (zlib's) of a tile's files: its heights, and its maps' when the set has them.
struct TileCrcs {
  uint32_t heights = 0;
  std::array<uint32_t, FT_MAP_COUNT> maps{};
};

// Builds tile (col, row) (or takes what the range pass kept of it) and
// writes it, and its maps when the set has them, into `dir` (temporary
// names, then renamed). Throws if a sample falls outside [height_min,
// height_max] (the range is then wrong).
TileCrcs write_tile(const TileTerrain& t, const TileSpec& spec, const std::string& dir, int32_t col, int32_t row);
// A generated terrain's tile (no erosion, no maps): its file's CRC-32.
inline uint32_t write_tile(const ft_terrain_params& p, const TileSpec& spec, const std::string& dir, int32_t col,
                           int32_t row) {
  return write_tile(TileTerrain::of(p), spec, dir, col, row).heights;
}

// The range pass's unit of work for an eroded set: builds tile (col, row),
// keeps it (and its maps) in the set's pending folder, and returns its
// heights' exact (min, max); a tile already kept there is read, not built.
std::pair<double, double> build_pending_tile(const TileTerrain& t, const TileSpec& spec, const std::string& dir,
                                             int32_t col, int32_t row);
// The pending folder of `spec` in `dir`; removing it; removing every other
// set's (stale: left by a range pass of a set that was never finished here).
std::string pending_path(const TileSpec& spec, const std::string& dir);
void remove_pending(const TileSpec& spec, const std::string& dir);
void remove_stale_pending(const TileSpec& spec, const std::string& dir);

// The 16-bit codes of `hf` on the common scale: round((z - min) 65535 /
// (max - min)), what every 16-bit tile holds. Throws FT_ERR_INTERNAL naming
// `what` for a height outside the range (the range is then wrong).
std::vector<uint16_t> quantise16(const Heightfield& hf, double height_min, double height_max, const std::string& what);

// CRC-32 of a file's bytes; throws FT_ERR_IO naming the file.
uint32_t file_crc32(const std::string& path);

}  // namespace ft::tiles
