// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/tileset_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/platform.hpp"
#include "io/heightfield_io.hpp"
#include "tiles/manifest.hpp"
#include "tiles/tile_terrain.hpp"
#include "tiles/tile_writer.hpp"

namespace ft::tiles {
namespace {

nlohmann::json finished_manifest(const std::string& dir) {
  std::optional<nlohmann::json> m = read_manifest(dir);
  if (!m) invalid("'" + dir + "' holds no tile set (no manifest.json)");
  if (!m->value("complete", false)) invalid("the tile set in '" + dir + "' is not finished; resume it first");
  return std::move(*m);
}

}  // namespace

void tileset_extent(const std::string& dir, int lod, int64_t* width, int64_t* height) {
  const nlohmann::json m = finished_manifest(dir);
  check_int_range("lod", lod, 0, 30);
  *width = (m["width"].get<int64_t>() - 1) / (int64_t(1) << lod) + 1;
  *height = (m["height"].get<int64_t>() - 1) / (int64_t(1) << lod) + 1;
}

namespace {

// The file of layer `map` (-1: the heights; else kMapNames' index) of tile entry `e`, and its recorded CRC-32.
std::pair<std::string, nlohmann::json> layer_file(const nlohmann::json& e, int map) {
  const std::string file = e["file"].get<std::string>();
  if (map < 0) return {file, e["crc32"]};
  const nlohmann::json c = e.value("maps_crc32", nlohmann::json());
  return {std::string("maps/") + kMapNames[size_t(map)] + "/" + file.substr(0, file.rfind('.')) + ".tif",
          c.is_array() ? c[size_t(map)] : nlohmann::json()};
}

Heightfield read_layer_window(const std::string& dir, int map, int lod, int64_t x0, int64_t y0, int32_t width,
                              int32_t height) {
  const nlohmann::json m = finished_manifest(dir);
  if (map >= 0 && !m.contains("maps"))
    invalid("the tile set in '" + dir + "' holds no maps; write it with its maps (fracterra tiles --maps)");
  int64_t ew = 0, eh = 0;
  tileset_extent(dir, lod, &ew, &eh);
  if (width < 1 || height < 1 || x0 < 0 || y0 < 0 || x0 + width > ew || y0 + height > eh)
    invalid("the window [" + std::to_string(x0) + ", " + std::to_string(x0 + width) + ") x [" + std::to_string(y0) +
            ", " + std::to_string(y0 + height) + ") is not inside the tile set's " + std::to_string(ew) + " x " +
            std::to_string(eh) + " samples at lod " + std::to_string(lod));
  check_allocation(checked_bytes(uint64_t(width), uint64_t(height), sizeof(float)), "the tile set window");
  const int64_t step = int64_t(1) << lod, tile = m["tile"].get<int64_t>();
  const int32_t columns = m["columns"].get<int32_t>();
  Heightfield out(width, height);
  // The whole's samples the window needs: gx = (x0 + i) step. Tile c holds
  // [c tile, c tile + tile]; a sample on a shared edge is read from the tile
  // it starts (both hold the same value).
  const int64_t gx0 = x0 * step, gx1 = (x0 + width - 1) * step, gy0 = y0 * step, gy1 = (y0 + height - 1) * step;
  const int32_t c0 = int32_t(std::min<int64_t>(gx0 / tile, columns - 1)), c1 = int32_t(std::min<int64_t>(gx1 / tile, columns - 1));
  const int32_t r0 = int32_t(std::min<int64_t>(gy0 / tile, m["rows"].get<int64_t>() - 1)),
                r1 = int32_t(std::min<int64_t>(gy1 / tile, m["rows"].get<int64_t>() - 1));
  for (int32_t r = r0; r <= r1; ++r)
    for (int32_t c = c0; c <= c1; ++c) {
      const nlohmann::json& e = m["tiles"][size_t(r) * size_t(columns) + size_t(c)];
      const auto [file, crc] = layer_file(e, map);
      const std::string path = platform::utf8_of(platform::fs_path(dir) / platform::fs_path(file));
      if (crc.is_null() || file_crc32(path) != crc.get<uint32_t>())
        fail(FT_ERR_IO, "the tile '" + path + "' is missing or damaged (its CRC-32 differs from the manifest's); "
                        "rerun fracterra tiles on the folder to rewrite it");
      const Heightfield t = io::read_heightfield(path);
      const int64_t tx0 = e["x0"].get<int64_t>(), ty0 = e["y0"].get<int64_t>();
      // The samples this tile contributes: those in [tx0, tx0 + tile) (its last column only when it is the whole's).
      const int64_t xe = c == columns - 1 ? tx0 + t.width() : tx0 + tile;
      const int64_t ye = r == m["rows"].get<int32_t>() - 1 ? ty0 + t.height() : ty0 + tile;
      // Window indices i with tx0 <= (x0 + i) step < xe, and likewise j.
      auto up = [step](int64_t v) { return (v + step - 1) / step; };
      const int64_t i0 = std::max<int64_t>(0, up(tx0) - x0), i1 = std::min<int64_t>(width, up(xe) - x0);
      const int64_t j0 = std::max<int64_t>(0, up(ty0) - y0), j1 = std::min<int64_t>(height, up(ye) - y0);
      for (int64_t j = j0; j < j1; ++j)
        for (int64_t i = i0; i < i1; ++i)
          out.at(int32_t(i), int32_t(j)) = t.at(int32_t((x0 + i) * step - tx0), int32_t((y0 + j) * step - ty0));
    }
  out.set_world_size(m["sample_spacing"].get<double>() * double(step) * double(width - 1));
  return out;
}

}  // namespace

Heightfield read_tileset_window(const std::string& dir, int lod, int64_t x0, int64_t y0, int32_t width,
                                int32_t height) {
  return read_layer_window(dir, -1, lod, x0, y0, width, height);
}

Heightfield read_tileset_map_window(const std::string& dir, const std::string& map, int lod, int64_t x0, int64_t y0,
                                    int32_t width, int32_t height) {
  return read_layer_window(dir, map_index(map), lod, x0, y0, width, height);
}

Heightfield read_tileset_whole(const std::string& dir, int lod) {
  int64_t w = 0, h = 0;
  tileset_extent(dir, lod, &w, &h);
  if (w > 65536 || h > 65536)
    invalid("the tile set in '" + dir + "' is " + std::to_string(w) + " x " + std::to_string(h) + " samples at lod " +
            std::to_string(lod) + ", more than one heightfield holds (65536 a side): read it at a coarser --lod");
  Heightfield hf = read_layer_window(dir, -1, lod, 0, 0, int32_t(w), int32_t(h));
  const double s = finished_manifest(dir)["sample_spacing"].get<double>() * double(int64_t(1) << lod);
  GeoReference g;
  g.has_transform = true;
  g.transform = {-0.5 * s, s, 0.0, 0.5 * s, 0.0, -s};  // pixel-is-area, north up (tile_geotransform's)
  hf.set_georef(g);
  return hf;
}

bool tileset_has_maps(const std::string& dir) { return finished_manifest(dir).contains("maps"); }

std::vector<float> tileset_window_colors(const std::string& dir, int lod, int64_t x0, int64_t y0, int32_t width,
                                         int32_t height, const ft_splat_params* layers, int32_t layer_count) {
  const nlohmann::json m = finished_manifest(dir);
  int64_t ew = 0, eh = 0;
  tileset_extent(dir, lod, &ew, &eh);
  if (width < 1 || height < 1 || x0 < 0 || y0 < 0 || x0 + width > ew || y0 + height > eh)
    invalid("the window is not inside the tile set's " + std::to_string(ew) + " x " + std::to_string(eh) +
            " samples at lod " + std::to_string(lod));
  const int64_t gx0 = std::max<int64_t>(0, x0 - 1), gy0 = std::max<int64_t>(0, y0 - 1);
  const int32_t gw = int32_t(std::min<int64_t>(ew, x0 + width + 1) - gx0);
  const int32_t gh = int32_t(std::min<int64_t>(eh, y0 + height + 1) - gy0);
  const Heightfield terrain = read_layer_window(dir, -1, lod, gx0, gy0, gw, gh);
  Heightfield deposited, area;
  splat::SplatInputs in{&terrain, nullptr, nullptr, nullptr};
  if (m.contains("maps")) {
    deposited = read_layer_window(dir, map_index("deposited"), lod, gx0, gy0, gw, gh);
    area = read_layer_window(dir, map_index("drainage_area"), lod, gx0, gy0, gw, gh);
    in.deposited = &deposited, in.drainage_area = &area;
  }
  const double lo = m["height_range"]["min"].get<double>(), hi = m["height_range"]["max"].get<double>();
  const double s = m["sample_spacing"].get<double>();
  const splat::SplatFrame frame{lo, hi - lo,
                                s * s * double(m["width"].get<int64_t>() - 1) * double(m["height"].get<int64_t>() - 1)};
  in.frame = &frame;
  std::vector<float> grown(terrain.size() * 4);
  splat::splat_colors_linear_rgba(in, layers, layer_count, 0, Progress(), grown.data());
  std::vector<float> out(size_t(width) * size_t(height) * 4);
  const int64_t ox = x0 - gx0, oy = y0 - gy0;
  for (int32_t j = 0; j < height; ++j)
    std::copy_n(grown.begin() + std::ptrdiff_t(((oy + j) * gw + ox) * 4), size_t(width) * 4,
                out.begin() + std::ptrdiff_t(size_t(j) * size_t(width) * 4));
  return out;
}

}  // namespace ft::tiles
