#include "tiles/tileset_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/platform.hpp"
#include "io/heightfield_io.hpp"
#include "tiles/manifest.hpp"
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

Heightfield read_tileset_window(const std::string& dir, int lod, int64_t x0, int64_t y0, int32_t width,
                                int32_t height) {
  const nlohmann::json m = finished_manifest(dir);
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
      const std::string path =
          platform::utf8_of(platform::fs_path(dir) / platform::fs_path(e["file"].get<std::string>()));
      if (e["crc32"].is_null() || file_crc32(path) != e["crc32"].get<uint32_t>())
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

}  // namespace ft::tiles
