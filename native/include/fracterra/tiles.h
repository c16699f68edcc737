/// @file fracterra/tiles.h
/// Tile sets: a terrain larger than memory written as tiles that share their
/// edge samples, with one height scale, a manifest (manifest.json) and a GDAL
/// VRT mosaic (docs/scale.md). The driver opens the set, writes each tile not
/// yet done with ft_tile_write (a pure function: any process, any order, safe
/// to retry), records its CRC-32 and finishes. Added in ABI 2.4.
#ifndef FRACTERRA_TILES_H
#define FRACTERRA_TILES_H

#include "core.h"
#include "terrain.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Tile file formats.
enum {
  FT_TILES_PNG16 = 0, ///< 16-bit PNG, (z - min) 65535 / (max - min), one range for the set; .pgw world file
  FT_TILES_TIFF = 1   ///< Cloud-Optimized GeoTIFF float32, exact heights, georeferenced
};

/// An open tile set folder (the driver's side). Free with ft_tileset_free.
typedef struct ft_tileset ft_tileset;

/// Opens or resumes the tile set of terrain `p` cut into tiles of `tile`
/// cells (tile + 1 samples, 2 <= tile <= 65536) in folder `dir` (created).
/// A folder holding another tile set's manifest is refused (FT_ERR_INVALID_ARGUMENT,
/// the message names the first difference). A new set's height range is
/// computed here (a bound from a coarse pass for midpoint, exact otherwise;
/// docs/scale.md) and its manifest written at once.
FT_API ft_status ft_tileset_open(const ft_terrain_params* p, int32_t tile, int32_t format, const char* dir,
                                 ft_tileset** out);
/// Like ft_tileset_open, but a new set whose height range needs the exact
/// pass over every tile (every method but plain midpoint and Mandelbrot) is
/// opened without one: *range_pending = 1, nothing is written yet, and the
/// driver runs the pass elsewhere, ft_tile_height_range once per tile (any
/// process, e.g. one Dask task each), then gives the union of the tiles'
/// ranges to ft_tileset_set_height_range before writing tiles. Otherwise as
/// ft_tileset_open, with *range_pending = 0. (ABI 2.10)
FT_API ft_status ft_tileset_open_deferred(const ft_terrain_params* p, int32_t tile, int32_t format, const char* dir,
                                          ft_tileset** out, int32_t* range_pending);
/// The exact height range of a set opened with its range pending: writes its
/// manifest. Refused when the range is not pending, not finite or min > max. (ABI 2.10)
FT_API ft_status ft_tileset_set_height_range(ft_tileset* set, double min, double max);
/// The exact height range of tile (column, row) of terrain `p` cut into
/// tiles of `tile` cells: the unit of work of the pass above. (ABI 2.10)
FT_API ft_status ft_tile_height_range(const ft_terrain_params* p, int32_t tile, int32_t column, int32_t row,
                                      double* min, double* max);
/// NULL-safe.
FT_API void ft_tileset_free(ft_tileset* set);
/// Tiles across and down.
FT_API ft_status ft_tileset_grid(const ft_tileset* set, int32_t* columns, int32_t* rows);
/// The common height range of the set (what ft_tile_write needs); refused
/// while it is pending (ft_tileset_open_deferred).
FT_API ft_status ft_tileset_height_range(const ft_tileset* set, double* min, double* max);
/// *done = 1 when the tile's file exists and its CRC-32 is the one recorded.
FT_API ft_status ft_tileset_tile_done(const ft_tileset* set, int32_t column, int32_t row, int32_t* done);
/// Records a written tile's CRC-32: appended to manifest.journal and flushed
/// to disk (folded into manifest.json on resume and at finish).
FT_API ft_status ft_tileset_record(ft_tileset* set, int32_t column, int32_t row, uint32_t crc32);
/// Every tile recorded: writes mosaic.vrt (+ .ovr overviews) and marks the manifest complete.
FT_API ft_status ft_tileset_finish(ft_tileset* set);

/// The whole set's samples per side at level of detail `lod` (every 2^lod-th
/// sample): (width - 1) / 2^lod + 1. `dir` holds a finished tile set. (ABI 2.7)
FT_API ft_status ft_tileset_extent(const char* dir, int32_t lod, int64_t* width, int64_t* height);
/// Reads the window [x0, x0 + width) x [y0, y0 + height), counted at level of
/// detail `lod` (sample (i, j) is sample ((x0 + i) 2^lod, (y0 + j) 2^lod) of
/// the whole), back from the tiles it touches (each checked against its
/// CRC-32): real heights (16-bit tiles to their common scale). For midpoint
/// sets a lod > 0 window is exactly the coarser stage. `*out` owns a new
/// heightfield whose world size is the window's extent. (ABI 2.7)
FT_API ft_status ft_tileset_read_window(const char* dir, int32_t lod, int64_t x0, int64_t y0, int32_t width,
                                        int32_t height, ft_heightfield** out);

/// Generates tile (column, row) of terrain `p` and writes it into `dir`
/// (temporary name, then rename); `*crc32` receives the CRC-32 (zlib) of the
/// file. The same arguments give the same bytes in any process. Fails if a
/// sample falls outside [height_min, height_max].
FT_API ft_status ft_tile_write(const ft_terrain_params* p, int32_t tile, int32_t format, double height_min,
                               double height_max, const char* dir, int32_t column, int32_t row, uint32_t* crc32);

#ifdef __cplusplus
}
#endif
#endif
