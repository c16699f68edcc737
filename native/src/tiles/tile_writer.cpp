#include "tiles/tile_writer.hpp"

#include <zlib.h>

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_raster.hpp"
#include "io/png_image.hpp"
#include "terrain/terrain.hpp"

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

TileSpec make_tile_spec(const ft_terrain_params& p, int64_t tile, TileFormat format, double height_min,
                        double height_max) {
  int64_t width = 0, height = 0;
  terrain::terrain_extent(p, 0, &width, &height);
  check_finite("height_min", height_min);
  check_finite("height_max", height_max);
  if (!(height_max >= height_min)) invalid("the height range's max must not be below its min");
  TileSpec s;
  s.grid = make_tile_grid(width, height, tile);
  s.format = format;
  s.height_min = height_min;
  s.height_max = height_max;
  s.spacing = p.world_size / double(width - 1);
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
  char name[64];
  std::snprintf(name, sizeof name, "tile_r%0*d_c%0*d.%s", d, row, d, col,
                spec.format == TileFormat::tiff ? "tif" : "png");
  return name;
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

uint32_t write_tile(const ft_terrain_params& p, const TileSpec& spec, const std::string& dir, int32_t col,
                    int32_t row) {
  spec.grid.check_tile(col, row);
  const terrain::Window w = spec.grid.window(col, row);
  Heightfield hf = terrain::generate_terrain_window(p, 0, w.x0, w.y0, w.width, w.height);
  double t[6];
  tile_geotransform(spec, col, row, t);
  const std::string path = platform::join_path(dir, tile_file_name(spec, col, row));
  if (spec.format == TileFormat::png16) {
    const GrayImage img = quantise(hf, spec, col, row);
    // The world file first: a tile that exists always has it (ESRI order:
    // x size, two rotations, y size, then the centre of the top-left pixel).
    char text[512];
    std::snprintf(text, sizeof text, "%.17g\n0\n0\n%.17g\n%.17g\n%.17g\n", t[1], t[5], t[0] + 0.5 * t[1],
                  t[3] + 0.5 * t[5]);
    io::write_file_atomically(path.substr(0, path.size() - 4) + ".pgw", text);
    io::write_png(path, img, io::PngEffort::fast);
  } else {
    GeoReference g;
    g.has_transform = true;
    for (int i = 0; i < 6; ++i) g.transform[size_t(i)] = t[i];
    hf.set_georef(g);
    io::write_cog(hf, path);
  }
  return file_crc32(path);
}

}  // namespace ft::tiles
