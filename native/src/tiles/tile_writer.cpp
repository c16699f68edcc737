// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/tile_writer.hpp"

#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include <filesystem>

#include "core/build_features.hpp"
#include "core/gdal_library.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_raster.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "terrain/terrain.hpp"
#include "tiles/manifest.hpp"

namespace ft::tiles {
namespace {

int digits(int64_t n) {
  int d = 1;
  while (n >= 10) n /= 10, ++d;
  return d;
}

// The quantised tile with the common range in its text chunks.
GrayImage quantise(const Heightfield& hf, const TileSpec& s, int32_t col, int32_t row) {
  GrayImage img;
  img.width = hf.width();
  img.height = hf.height();
  img.bit_depth = 16;
  img.pixels = quantise16(hf, s.height_min, s.height_max,
                          "tile (column " + std::to_string(col) + ", row " + std::to_string(row) + ")");
  img.text["fracterra:min"] = format_number(s.height_min);
  img.text["fracterra:max"] = format_number(s.height_max);
  img.text["fracterra:world_size"] = format_number(s.spacing * (hf.width() - 1));
  img.text["Software"] = "fracterra";
  return img;
}

}  // namespace

std::vector<uint16_t> quantise16(const Heightfield& hf, double height_min, double height_max, const std::string& what) {
  std::vector<uint16_t> codes(hf.size());
  const double range = height_max - height_min;
  const double k = range > 0 ? 65535.0 / range : 0.0;
  const float* z = hf.data();
  for (size_t i = 0; i < hf.size(); ++i) {
    const double q = std::nearbyint((double(z[i]) - height_min) * k);
    if (!(q >= 0.0 && q <= 65535.0))
      fail(FT_ERR_INTERNAL, what + " has the height " + format_number(z[i]) + ", outside the tile set's range [" +
                                format_number(height_min) + ", " + format_number(height_max) + "]");
    codes[i] = uint16_t(q);
  }
  return codes;
}

namespace {

// An eroded set's tiles are all of one size, as game engines take them and
// so that one figure bounds every task's memory: the tile must cut the whole.
void check_tile_cuts(int64_t width, int64_t height, int64_t tile) {
  if (tile >= 2 && (width - 1) % tile == 0 && (height - 1) % tile == 0) return;
  const int64_t g = std::gcd(width - 1, height - 1);
  std::string sizes;
  int listed = 0;
  for (int64_t d = std::min<int64_t>(g, 65536); d >= 2 && listed < 8; --d)
    if (g % d == 0) sizes += (listed++ ? ", " : "") + std::to_string(d);
  invalid("an eroded tile set's tiles are all of one size: --tile " + std::to_string(tile) + " does not cut the " +
          std::to_string(width) + " x " + std::to_string(height) + " terrain (width - 1 and height - 1 must be " +
          "multiples of it); " + (sizes.empty() ? std::string("no size does") : "sizes that do: " + sizes));
}

// A mask spans the whole terrain corner to corner: one of another shape
// would be stretched, which for a whole that is never seen is a mask made
// for another terrain. Its shape must be the whole's to within one sample.
void check_mask_shape(const char* what, const void* mask, int32_t mw, int32_t mh, int64_t width, int64_t height) {
  if (mask == nullptr) return;
  const double want = double(mh - 1) * double(width - 1) / double(height - 1);
  if (std::abs(double(mw - 1) - want) <= 1.0) return;
  invalid(std::string(what) + " is " + std::to_string(mw) + " x " + std::to_string(mh) + "; it spans the whole " +
          std::to_string(width) + " x " + std::to_string(height) + " terrain and must have its shape (" +
          std::to_string(int64_t(std::llround(want)) + 1) + " x " + std::to_string(mh) + ", or the terrain's own size)");
}

}  // namespace

TileSpec make_tile_spec(const TileTerrain& t, int64_t tile, TileFormat format, double height_min,
                        double height_max) {
  const ft_terrain_params& p = t.terrain;
  int64_t width = 0, height = 0;
  terrain::terrain_extent(p, 0, &width, &height);
  if (t.maps && !have_gdal()) needs_gdal("a tile set's maps (float32 GeoTIFFs; leave out the maps to go without)");
  if (t.erodes()) {
    check_tile_cuts(width, height, tile);
    check_mask_shape("the falloff mask", p.falloff == FT_FALLOFF_CUSTOM ? p.falloff_mask : nullptr,
                     p.falloff_mask_width, p.falloff_mask_height, width, height);
    if (t.has_erosion) {
      check_mask_shape("the erosion mask", t.erosion.erosion_mask, t.erosion.erosion_mask_width,
                       t.erosion.erosion_mask_height, width, height);
      check_mask_shape("the rain map", t.erosion.rain_map, t.erosion.rain_map_width, t.erosion.rain_map_height, width,
                       height);
    }
  }
  check_finite("height_min", height_min);
  check_finite("height_max", height_max);
  if (!(height_max >= height_min)) invalid("the height range's max must not be below its min");
  TileSpec s;
  s.grid = make_tile_grid(width, height, tile);
  s.format = format;
  s.height_min = height_min;
  s.height_max = height_max;
  s.spacing = p.world_size / double(width - 1);
  s.maps = t.maps;
  if (t.erodes()) {
    // Named after the set's identity: what another set's range pass left is never taken for this one's.
    const std::string id = tileset_identity(t, tile, format_name(format)).dump();
    char name[32];
    std::snprintf(name, sizeof name, ".pending-%08x", unsigned(crc32_z(crc32(0L, Z_NULL, 0),
                                                                         reinterpret_cast<const Bytef*>(id.data()), id.size())));
    s.pending = name;
  }
  return s;
}

const char* format_name(TileFormat f) { return f == TileFormat::tiff ? "tiff" : "png16"; }

TileFormat parse_tile_format(const std::string& name) {
  if (name == "png16" || name == "png") return TileFormat::png16;
  if (name == "tiff" || name == "tif") return TileFormat::tiff;
  invalid("the tile format must be png16 (16-bit PNG, one height scale) or tiff (float32 GeoTIFF), got '" + name +
          "'");
}

std::string tile_file_name(const TileSpec& spec, int32_t col, int32_t row) {
  const int d = std::max(3, digits(std::max(spec.grid.columns(), spec.grid.rows()) - 1));
  // Zero-padded to one width, so the names sort as the grid does.
  auto padded = [d](int32_t v) {
    const std::string s = std::to_string(v);
    return std::string(size_t(std::max(0, d - int(s.size()))), '0') + s;
  };
  return "tile_r" + padded(row) + "_c" + padded(col) + (spec.format == TileFormat::tiff ? ".tif" : ".png");
}

std::string map_file_name(const TileSpec& spec, int k, int32_t col, int32_t row) {
  std::string name = tile_file_name(spec, col, row);
  name = name.substr(0, name.rfind('.')) + ".tif";
  return std::string("maps/") + kMapNames[size_t(k)] + "/" + name;
}

void tile_geotransform(const TileSpec& spec, int32_t col, int32_t row, double t[6]) {
  const terrain::Window w = spec.grid.window(col, row);
  const double s = spec.spacing;
  t[0] = (double(w.x0) - 0.5) * s;
  t[1] = s;
  t[2] = 0.0;
  t[3] = -(double(w.y0) - 0.5) * s;
  t[4] = 0.0;
  t[5] = -s;
}

uint32_t file_crc32(const std::string& path) {
  const std::string bytes = io::read_file(path);
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes 32-bit lengths: feed large files in pieces.
  for (size_t at = 0; at < bytes.size(); at += size_t(1) << 30) {
    const size_t n = std::min(bytes.size() - at, size_t(1) << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), uInt(n));
  }
  return uint32_t(crc);
}

namespace {

namespace fs = std::filesystem;

GeoReference georef_of(const TileSpec& spec, int32_t col, int32_t row) {
  double t[6];
  tile_geotransform(spec, col, row, t);
  GeoReference g;
  g.has_transform = true;
  for (int i = 0; i < 6; ++i) g.transform[size_t(i)] = t[i];
  return g;
}

void make_parent(const std::string& path) {
  std::error_code ec;
  fs::create_directories(platform::fs_path(path).parent_path(), ec);
  if (ec) fail(FT_ERR_IO, "cannot create the folder of '" + path + "': " + ec.message());
}

// Map k of a tile, georeferenced, as a float32 GeoTIFF at `path`.
void write_map(Heightfield& map, const TileSpec& spec, int32_t col, int32_t row, const std::string& path) {
  map.set_georef(georef_of(spec, col, row));
  make_parent(path);
  io::write_cog(map, path);
}

std::string pending_heights(const TileSpec& spec, const std::string& dir, int32_t col, int32_t row) {
  std::string name = tile_file_name(spec, col, row);
  return platform::join_path(pending_path(spec, dir), name.substr(0, name.rfind('.')) + ".npy");
}

std::string pending_map(const TileSpec& spec, const std::string& dir, int k, int32_t col, int32_t row) {
  return platform::join_path(pending_path(spec, dir), map_file_name(spec, k, col, row));
}

bool exists(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(platform::fs_path(path), ec);
}

// What the range pass kept of the tile: its heights when they and every map are there.
bool kept(const TileSpec& spec, const std::string& dir, int32_t col, int32_t row) {
  if (spec.pending.empty() || !exists(pending_heights(spec, dir, col, row))) return false;
  for (int k = 0; spec.maps && k < FT_MAP_COUNT; ++k)
    if (!exists(pending_map(spec, dir, k, col, row))) return false;
  return true;
}

// The kept heights, checked against the tile's size (a file of another size is not this tile's).
Heightfield read_kept(const TileSpec& spec, const std::string& dir, int32_t col, int32_t row) {
  const terrain::Window w = spec.grid.window(col, row);
  Heightfield hf = io::read_heightfield(pending_heights(spec, dir, col, row));
  if (hf.width() != w.width || hf.height() != w.height)
    fail(FT_ERR_IO, "'" + pending_heights(spec, dir, col, row) + "' is not tile (column " + std::to_string(col) +
                        ", row " + std::to_string(row) + ") of this set; remove the folder " + spec.pending);
  hf.set_world_size(spec.spacing * double(w.width - 1));
  return hf;
}

}  // namespace

std::string pending_path(const TileSpec& spec, const std::string& dir) {
  if (spec.pending.empty()) invalid("only an eroded tile set has a pending folder");
  return platform::join_path(dir, spec.pending);
}

void remove_pending(const TileSpec& spec, const std::string& dir) {
  if (spec.pending.empty()) return;
  std::error_code ec;
  fs::remove_all(platform::fs_path(pending_path(spec, dir)), ec);
  if (ec) fail(FT_ERR_IO, "cannot remove '" + pending_path(spec, dir) + "': " + ec.message());
}

void remove_stale_pending(const TileSpec& spec, const std::string& dir) {
  std::error_code ec;
  std::vector<fs::path> stale;  // collected first: removing while iterating is unspecified
  for (const fs::directory_entry& e : fs::directory_iterator(platform::fs_path(dir), ec)) {
    const std::string name = platform::utf8_of(e.path().filename());
    if (e.is_directory() && name.rfind(".pending-", 0) == 0 && name != spec.pending) stale.push_back(e.path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

std::pair<double, double> build_pending_tile(const TileTerrain& t, const TileSpec& spec, const std::string& dir,
                                             int32_t col, int32_t row) {
  spec.grid.check_tile(col, row);
  if (kept(spec, dir, col, row)) {
    const HeightStats s = read_kept(spec, dir, col, row).stats();
    return {s.min, s.max};
  }
  erosion::ErosionMaps maps;
  const Heightfield hf = build_window(t, spec.grid.window(col, row), spec.maps ? &maps : nullptr);
  for (int k = 0; spec.maps && k < FT_MAP_COUNT; ++k)
    write_map(map_of(maps, k), spec, col, row, pending_map(spec, dir, k, col, row));
  // The heights last: when they are there, the maps are too.
  const std::string path = pending_heights(spec, dir, col, row);
  make_parent(path);
  io::write_heightfield(hf, path);
  const HeightStats s = hf.stats();
  return {s.min, s.max};
}

TileCrcs write_tile(const TileTerrain& t, const TileSpec& spec, const std::string& dir, int32_t col, int32_t row) {
  spec.grid.check_tile(col, row);
  const terrain::Window w = spec.grid.window(col, row);
  TileCrcs crcs;
  const bool from_pending = kept(spec, dir, col, row);
  erosion::ErosionMaps maps;
  Heightfield hf = from_pending ? read_kept(spec, dir, col, row) : build_window(t, w, spec.maps ? &maps : nullptr);
  for (int k = 0; spec.maps && k < FT_MAP_COUNT; ++k) {
    const std::string path = platform::join_path(dir, map_file_name(spec, k, col, row));
    if (from_pending) {  // the range pass wrote it as it is: moved into place
      make_parent(path);
      fs::rename(platform::fs_path(pending_map(spec, dir, k, col, row)), platform::fs_path(path));
    } else {
      write_map(map_of(maps, k), spec, col, row, path);
    }
    crcs.maps[size_t(k)] = file_crc32(path);
  }
  double tr[6];
  tile_geotransform(spec, col, row, tr);
  const std::string path = platform::join_path(dir, tile_file_name(spec, col, row));
  if (spec.format == TileFormat::png16) {
    const GrayImage img = quantise(hf, spec, col, row);
    // The world file first: a tile that exists always has it (ESRI order:
    // x size, two rotations, y size, then the centre of the top-left pixel).
    char text[512];
    std::snprintf(text, sizeof text, "%.17g\n0\n0\n%.17g\n%.17g\n%.17g\n", tr[1], tr[5], tr[0] + 0.5 * tr[1],
                  tr[3] + 0.5 * tr[5]);
    io::write_file_atomically(path.substr(0, path.size() - 4) + ".pgw", text);
    io::write_png(path, img, io::PngEffort::fast);
  } else {
    hf.set_georef(georef_of(spec, col, row));
    io::write_cog(hf, path);
  }
  crcs.heights = file_crc32(path);
  if (from_pending) {
    std::error_code ec;
    fs::remove(platform::fs_path(pending_heights(spec, dir, col, row)), ec);
  }
  return crcs;
}

}  // namespace ft::tiles
