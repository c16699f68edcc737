// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/tiles.h
/// Tile sets: a terrain larger than memory written as tiles that share their
/// edge samples, with one height scale, a manifest (manifest.json) and a GDAL
/// VRT mosaic (docs/scale.md). The driver opens the set, writes each tile not
/// yet done with ft_tile_write (a pure function: any process, any order, safe
/// to retry), records its CRC-32 and finishes. Added in ABI 2.4.
#ifndef FRACTERRA_TILES_H
#define FRACTERRA_TILES_H

#include "core.h"
#include "pipeline.h"
#include "splat.h"
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

/// Tile sets of built terrains (ABI 2.26): the terrain, its landform and its
/// erosion as ft_terrain_build makes them (`p`), each tile the window of the
/// built terrain (ft_terrain_build_window), bit-identical to the same samples
/// of the whole, so an eroded set has no seams. p's progress is ignored.
/// With `maps` non-zero the set also holds the maps (ft_erosion_map order),
/// each tile's as a float32 GeoTIFF maps/<map>/tile_rRRR_cCCC.tif, mosaicked
/// in maps/<map>.vrt (needs GDAL). The manifest records the erosion (the
/// preset and every setting it erodes with) and the maps: a folder holding a
/// set of another terrain, erosion or maps is refused naming the first
/// difference. An eroded set's height range is the exact union of its
/// tiles', so it is always pending here when new (*range_pending = 1) unless
/// `defer` is 0, which runs the pass in this call. Without erosion and maps
/// the set is byte-identical to ft_tileset_open_deferred's.
FT_API ft_status ft_tileset_open_build(const ft_build_params* p, int32_t tile, int32_t format, int32_t maps,
                                       int32_t defer, const char* dir, ft_tileset** out, int32_t* range_pending);
/// The range pass's task for a set of ft_tileset_open_build (any process, any
/// order, safe to retry): the exact height range of tile (column, row). An
/// eroded tile is built once here and kept in the set's folder `dir` (a
/// hidden .pending-XXXXXXXX folder named after the set), where
/// ft_tile_write_build takes it instead of building it again; the set's
/// finish removes the folder. Arguments as ft_tileset_open_build's. (ABI 2.26)
FT_API ft_status ft_tile_build_range(const ft_build_params* p, int32_t tile, int32_t format, int32_t maps,
                                     const char* dir, int32_t column, int32_t row, double* min, double* max);
/// Writes tile (column, row) of a set of ft_tileset_open_build into `dir`:
/// its heights, and its maps when `maps` is non-zero (temporary names, then
/// renamed). `crcs` receives `crc_count` CRC-32s: the heights file's, then
/// with maps one per map in ft_erosion_map order; crc_count must be 1, or
/// 1 + FT_MAP_COUNT with maps. The same arguments give the same bytes in any
/// process. Fails if a sample falls outside [height_min, height_max]. (ABI 2.26)
FT_API ft_status ft_tile_write_build(const ft_build_params* p, int32_t tile, int32_t format, int32_t maps,
                                     double height_min, double height_max, const char* dir, int32_t column,
                                     int32_t row, uint32_t* crcs, int32_t crc_count);
/// Records a tile's CRC-32s as ft_tile_write_build gave them (crc_count 1, or
/// 1 + FT_MAP_COUNT for a set with maps). (ABI 2.26)
FT_API ft_status ft_tileset_record_tile(ft_tileset* set, int32_t column, int32_t row, const uint32_t* crcs,
                                        int32_t crc_count);
/// As ft_tileset_read_window, for map `map` (FT_MAP_*) of a finished set with
/// maps: exact float32 values in the map's units. (ABI 2.26)
FT_API ft_status ft_tileset_read_map_window(const char* dir, int32_t map, int32_t lod, int64_t x0, int64_t y0,
                                            int32_t width, int32_t height, ft_heightfield** out);
/// The colours of splat rules `layers` (splat.h; layer_count of them) over the
/// window of ft_tileset_read_window, in linear RGBA as
/// ft_splat_colors_linear_rgba gives them (rgba: 4 width height floats), equal
/// to the whole's: the rules see the whole set's height range and area, its
/// maps' deposits and flow (a set without maps: none) and slopes across the
/// window's edges. (ABI 2.26)
FT_API ft_status ft_tileset_window_colors(const char* dir, int32_t lod, int64_t x0, int64_t y0, int32_t width,
                                          int32_t height, const ft_splat_params* layers, int32_t layer_count,
                                          float* rgba, size_t rgba_count);
/// Cuts the finished set in `dir` the way game engine `engine` ("unity",
/// "unreal", "godot") imports a large terrain in pieces, into `out_dir`
/// (created) with `out_dir/<engine>.json` (docs/engines.md): engine tiles of
/// `side` samples (0: the set's own tiles when the engine takes them, else
/// the largest that cuts the set), Godot regions of `region_size`. An eroded
/// set with its maps gets the default splat rules' maps per tile too (Unity:
/// an RGBA alphamap, Unreal: a weight map per layer, Godot: a control map),
/// equal to the whole's. What the engine cannot take is refused before
/// anything is written. (ABI 2.26)
FT_API ft_status ft_tileset_cut_for_engine(const char* dir, const char* engine, int32_t side, int32_t region_size,
                                           const char* out_dir);

#ifdef __cplusplus
}
#endif
#endif
