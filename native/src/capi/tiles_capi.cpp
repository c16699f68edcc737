// The C ABI of tile sets (fracterra/tiles.h).
#include <memory>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/tiles.h"
#include "terrain/terrain_params.hpp"
#include "tiles/height_range.hpp"
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
    s->set = std::make_unique<ft::tiles::TileSet>(ft::upgraded(ft::terrain::terrain_param_table(), *p), tile, format_of(format), dir);
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
    s->set = std::make_unique<ft::tiles::TileSet>(ft::upgraded(ft::terrain::terrain_param_table(), *p), tile, format_of(format), dir,
                                           true);
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
    const ft_terrain_params q = ft::upgraded(ft::terrain::terrain_param_table(), *p);
    const ft::tiles::TileSpec spec = ft::tiles::make_tile_spec(q, tile, ft::tiles::TileFormat::tiff);
    const ft::tiles::HeightRange r = ft::tiles::tile_height_range(q, spec.grid, column, row);
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
    set->set->record(column, row, crc32);
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
    const ft_terrain_params q = ft::upgraded(ft::terrain::terrain_param_table(), *p);
    const ft::tiles::TileSpec spec = ft::tiles::make_tile_spec(q, tile, format_of(format), height_min, height_max);
    *crc32 = ft::tiles::write_tile(q, spec, dir, column, row);
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
