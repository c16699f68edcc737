// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI of tile sets (fracterra/tiles.h).
#include <algorithm>
#include <memory>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "engines/engine_tiles.hpp"
#include "fracterra/tiles.h"
#include "terrain/terrain_params.hpp"
#include "tiles/height_range.hpp"
#include "tiles/tile_terrain.hpp"
#include "tiles/tileset.hpp"
#include "tiles/tileset_reader.hpp"

struct ft_tileset {
  std::unique_ptr<ft::tiles::TileSet> set;
};

using ft::capi::guarded;

namespace {

ft::tiles::TileFormat format_of(int32_t format) {
  if (format != FT_TILES_PNG16 && format != FT_TILES_TIFF)
    ft::invalid("format must be FT_TILES_PNG16 (0) or FT_TILES_TIFF (1), got " + std::to_string(format));
  return ft::tiles::TileFormat(format);
}

ft::tiles::TileTerrain built_terrain(const ft_build_params* p, int32_t maps) {
  ft::check_not_null("params", p);
  return ft::tiles::TileTerrain::of(*p, maps != 0);
}

// crcs[0 .. count) as a tile's CRC-32s, checked against the set's maps.
ft::tiles::TileCrcs crcs_of(const uint32_t* crcs, int32_t count, bool maps) {
  ft::check_not_null("crcs", crcs);
  const int32_t want = maps ? 1 + FT_MAP_COUNT : 1;
  if (count != want)
    ft::invalid("crc_count must be " + std::to_string(want) + (maps ? " (the heights and one per map)" : " (the heights)") +
                ", got " + std::to_string(count));
  ft::tiles::TileCrcs c;
  c.heights = crcs[0];
  for (int k = 0; maps && k < FT_MAP_COUNT; ++k) c.maps[size_t(k)] = crcs[1 + k];
  return c;
}

const ft::tiles::TileSet& set_of(const ft_tileset* s) {
  ft::check_not_null("set", s);
  return *s->set;
}

}  // namespace

FT_API ft_status ft_tileset_open(const ft_terrain_params* p, int32_t tile, int32_t format, const char* dir,
                                 ft_tileset** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("params", p);
    ft::check_not_null("dir", dir);
    auto s = std::make_unique<ft_tileset>();
    s->set = std::make_unique<ft::tiles::TileSet>(ft::tiles::TileTerrain::of(*p), tile, format_of(format), dir);
    *out = s.release();
  });
}

FT_API ft_status ft_tileset_open_deferred(const ft_terrain_params* p, int32_t tile, int32_t format, const char* dir,
                                          ft_tileset** out, int32_t* range_pending) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("params", p);
    ft::check_not_null("dir", dir);
    ft::check_not_null("range_pending", range_pending);
    *range_pending = 0;
    auto s = std::make_unique<ft_tileset>();
    s->set = std::make_unique<ft::tiles::TileSet>(ft::tiles::TileTerrain::of(*p), tile, format_of(format), dir, true);
    *range_pending = s->set->range_pending() ? 1 : 0;
    *out = s.release();
  });
}

FT_API ft_status ft_tileset_set_height_range(ft_tileset* set, double min, double max) {
  return guarded([&] {
    ft::check_not_null("set", set);
    set->set->set_height_range(min, max);
  });
}

FT_API ft_status ft_tile_height_range(const ft_terrain_params* p, int32_t tile, int32_t column, int32_t row,
                                      double* min, double* max) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("min", min);
    ft::check_not_null("max", max);
    *min = *max = 0;
    const ft::tiles::TileTerrain t = ft::tiles::TileTerrain::of(*p);
    const ft::tiles::TileSpec spec = ft::tiles::make_tile_spec(t, tile, ft::tiles::TileFormat::tiff);
    const ft::tiles::HeightRange r = ft::tiles::tile_height_range(t.terrain, spec.grid, column, row);
    *min = r.min, *max = r.max;
  });
}

FT_API void ft_tileset_free(ft_tileset* set) { delete set; }

FT_API ft_status ft_tileset_grid(const ft_tileset* set, int32_t* columns, int32_t* rows) {
  return guarded([&] {
    ft::check_not_null("columns", columns);
    ft::check_not_null("rows", rows);
    *columns = set_of(set).spec().grid.columns();
    *rows = set_of(set).spec().grid.rows();
  });
}

FT_API ft_status ft_tileset_height_range(const ft_tileset* set, double* min, double* max) {
  return guarded([&] {
    ft::check_not_null("min", min);
    ft::check_not_null("max", max);
    if (set_of(set).range_pending())
      ft::invalid("the tile set's height range is pending: give it with ft_tileset_set_height_range");
    *min = set_of(set).spec().height_min;
    *max = set_of(set).spec().height_max;
  });
}

FT_API ft_status ft_tileset_tile_done(const ft_tileset* set, int32_t column, int32_t row, int32_t* done) {
  return guarded([&] {
    ft::check_not_null("done", done);
    *done = set_of(set).done(column, row) ? 1 : 0;
  });
}

FT_API ft_status ft_tileset_record(ft_tileset* set, int32_t column, int32_t row, uint32_t crc32) {
  return guarded([&] {
    ft::check_not_null("set", set);
    if (set->set->spec().maps) ft::invalid("the tile set holds maps: record its tiles with ft_tileset_record_tile");
    ft::tiles::TileCrcs c;
    c.heights = crc32;
    set->set->record(column, row, c);
  });
}

FT_API ft_status ft_tileset_finish(ft_tileset* set) {
  return guarded([&] {
    ft::check_not_null("set", set);
    set->set->finish();
  });
}

FT_API ft_status ft_tile_write(const ft_terrain_params* p, int32_t tile, int32_t format, double height_min,
                               double height_max, const char* dir, int32_t column, int32_t row, uint32_t* crc32) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_not_null("dir", dir);
    ft::check_not_null("crc32", crc32);
    *crc32 = 0;
    const ft::tiles::TileTerrain t = ft::tiles::TileTerrain::of(*p);
    const ft::tiles::TileSpec spec = ft::tiles::make_tile_spec(t, tile, format_of(format), height_min, height_max);
    *crc32 = ft::tiles::write_tile(t, spec, dir, column, row).heights;
  });
}

FT_API ft_status ft_tileset_open_build(const ft_build_params* p, int32_t tile, int32_t format, int32_t maps,
                                       int32_t defer, const char* dir, ft_tileset** out, int32_t* range_pending) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("dir", dir);
    ft::check_not_null("range_pending", range_pending);
    *range_pending = 0;
    auto s = std::make_unique<ft_tileset>();
    s->set = std::make_unique<ft::tiles::TileSet>(built_terrain(p, maps), tile, format_of(format), dir, defer != 0);
    *range_pending = s->set->range_pending() ? 1 : 0;
    *out = s.release();
  });
}

FT_API ft_status ft_tile_build_range(const ft_build_params* p, int32_t tile, int32_t format, int32_t maps,
                                     const char* dir, int32_t column, int32_t row, double* min, double* max) {
  return guarded([&] {
    ft::check_not_null("dir", dir);
    ft::check_not_null("min", min);
    ft::check_not_null("max", max);
    *min = *max = 0;
    const ft::tiles::TileTerrain t = built_terrain(p, maps);
    const ft::tiles::TileSpec spec = ft::tiles::make_tile_spec(t, tile, format_of(format));
    const ft::tiles::HeightRange r = ft::tiles::tile_height_range(t, spec, dir, column, row);
    *min = r.min, *max = r.max;
  });
}

FT_API ft_status ft_tile_write_build(const ft_build_params* p, int32_t tile, int32_t format, int32_t maps,
                                     double height_min, double height_max, const char* dir, int32_t column,
                                     int32_t row, uint32_t* crcs, int32_t crc_count) {
  return guarded([&] {
    ft::check_not_null("dir", dir);
    crcs_of(crcs, crc_count, maps != 0);  // checks the count before any work
    for (int32_t k = 0; k < crc_count; ++k) crcs[k] = 0;
    const ft::tiles::TileTerrain t = built_terrain(p, maps);
    const ft::tiles::TileSpec spec = ft::tiles::make_tile_spec(t, tile, format_of(format), height_min, height_max);
    const ft::tiles::TileCrcs c = ft::tiles::write_tile(t, spec, dir, column, row);
    crcs[0] = c.heights;
    for (int k = 0; t.maps && k < FT_MAP_COUNT; ++k) crcs[1 + k] = c.maps[size_t(k)];
  });
}

FT_API ft_status ft_tileset_record_tile(ft_tileset* set, int32_t column, int32_t row, const uint32_t* crcs,
                                        int32_t crc_count) {
  return guarded([&] {
    ft::check_not_null("set", set);
    set->set->record(column, row, crcs_of(crcs, crc_count, set->set->spec().maps));
  });
}

FT_API ft_status ft_tileset_extent(const char* dir, int32_t lod, int64_t* width, int64_t* height) {
  return guarded([&] {
    ft::check_not_null("dir", dir);
    ft::check_not_null("width", width);
    ft::check_not_null("height", height);
    *width = *height = 0;
    ft::tiles::tileset_extent(dir, lod, width, height);
  });
}

FT_API ft_status ft_tileset_read_window(const char* dir, int32_t lod, int64_t x0, int64_t y0, int32_t width,
                                        int32_t height, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("dir", dir);
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::tiles::read_tileset_window(dir, lod, x0, y0, width, height);
    *out = h.release();
  });
}

FT_API ft_status ft_tileset_read_map_window(const char* dir, int32_t map, int32_t lod, int64_t x0, int64_t y0,
                                            int32_t width, int32_t height, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("dir", dir);
    ft::check_int_range("map", map, 0, FT_MAP_COUNT - 1);
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::tiles::read_tileset_map_window(dir, ft::tiles::kMapNames[size_t(map)], lod, x0, y0, width, height);
    *out = h.release();
  });
}

FT_API ft_status ft_tileset_cut_for_engine(const char* dir, const char* engine, int32_t side, int32_t region_size,
                                           const char* out_dir) {
  return guarded([&] {
    ft::check_not_null("dir", dir);
    ft::check_not_null("engine", engine);
    ft::check_not_null("out_dir", out_dir);
    ft::engines::write_engine_tiles(dir, out_dir, {ft::engines::parse_engine(engine), region_size, side});
  });
}

FT_API ft_status ft_tileset_window_colors(const char* dir, int32_t lod, int64_t x0, int64_t y0, int32_t width,
                                          int32_t height, const ft_splat_params* layers, int32_t layer_count,
                                          float* rgba, size_t rgba_count) {
  return guarded([&] {
    ft::check_not_null("dir", dir);
    ft::check_not_null("layers", layers);
    ft::check_not_null("rgba", rgba);
    if (width < 1 || height < 1 || rgba_count != size_t(width) * size_t(height) * 4)
      ft::invalid("rgba_count must be 4 x width x height for a window of at least 1 x 1");
    const std::vector<float> c =
        ft::tiles::tileset_window_colors(dir, lod, x0, y0, width, height, layers, layer_count);
    std::copy(c.begin(), c.end(), rgba);
  });
}
