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
// Map coordinates: sample (x, y) of the whole terrain is at
// (x s, -y s), s = world_size / (width - 1) the sample spacing, north up.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/heightfield.hpp"
#include "terrain/terrain.hpp"  // ft_terrain_params
#include "tiles/tile_grid.hpp"

namespace ft::tiles {

enum class TileFormat { png16 = 0, tiff = 1 };

struct TileSpec {
  TileGrid grid;
  TileFormat format = TileFormat::png16;
  double height_min = 0, height_max = 1;  // the common scale of 16-bit tiles
  double spacing = 1;                      // world units between neighbouring samples
};

// The spec of terrain `p` cut into tiles of `tile` cells (validates p for
// windows: spectral and out-of-range sizes are refused there).
TileSpec make_tile_spec(const ft_terrain_params& p, int64_t tile, TileFormat format, double height_min = 0,
                        double height_max = 1);

const char* format_name(TileFormat f);     // "png16", "tiff"
TileFormat parse_tile_format(const std::string& name);  // throws naming the choices
// "tile_r003_c012.png": zero-padded to the grid's digits.
std::string tile_file_name(const TileSpec& spec, int32_t col, int32_t row);
// GDAL's geotransform of tile (col, row) (pixel-is-area: its top-left corner
// is half a spacing up and left of its first sample).
void tile_geotransform(const TileSpec& spec, int32_t col, int32_t row, double transform[6]);

// Generates tile (col, row) and writes it into `dir` (temporary name, then
// rename). Returns the CRC-32 (zlib's) of the file's bytes. Throws if a
// sample falls outside [height_min, height_max] (the range is then wrong).
uint32_t write_tile(const ft_terrain_params& p, const TileSpec& spec, const std::string& dir, int32_t col, int32_t row);

// The 16-bit codes of `hf` on the common scale: round((z - min) 65535 /
// (max - min)), what every 16-bit tile holds. Throws FT_ERR_INTERNAL naming
// `what` for a height outside the range (the range is then wrong).
std::vector<uint16_t> quantise16(const Heightfield& hf, double height_min, double height_max, const std::string& what);

// CRC-32 of a file's bytes; throws FT_ERR_IO naming the file.
uint32_t file_crc32(const std::string& path);

}  // namespace ft::tiles
