// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/tileset.hpp"

#include <cmath>
#include <filesystem>
#include <optional>

#include "core/build_features.hpp"
#include "core/gdal_library.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "terrain/terrain.hpp"
#include "tiles/manifest.hpp"
#include "tiles/mosaic_vrt.hpp"

namespace ft::tiles {
namespace {

void make_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path folder = platform::fs_path(dir);
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    fail(FT_ERR_IO, "'" + dir + "' exists and is not a folder");
  fs::create_directories(folder, ec);
  if (ec) fail(FT_ERR_IO, "cannot create the folder '" + dir + "': " + ec.message());
}

nlohmann::json new_manifest(const nlohmann::json& identity, const TileSpec& s, const HeightRange& r) {
  nlohmann::json m = identity;
  m.update({{"format", "fracterra-tileset"},
                      {"version", 1},
                      {"width", s.grid.width},
                      {"height", s.grid.height},
                      {"columns", s.grid.columns()},
                      {"rows", s.grid.rows()},
                      {"sample_spacing", s.spacing},
                      {"world_size", {s.spacing * double(s.grid.width - 1), s.spacing * double(s.grid.height - 1)}},
                      {"height_range", {{"min", r.min}, {"max", r.max}, {"how", r.how}}},
                      {"complete", false}});
  nlohmann::json tiles = nlohmann::json::array();
  for (int32_t row = 0; row < s.grid.rows(); ++row)
    for (int32_t col = 0; col < s.grid.columns(); ++col) {
      const terrain::Window w = s.grid.window(col, row);
      tiles.push_back({{"column", col},
                       {"row", row},
                       {"file", tile_file_name(s, col, row)},
                       {"x0", w.x0},
                       {"y0", w.y0},
                       {"width", w.width},
                       {"height", w.height},
                       {"crc32", nullptr}});
      if (s.maps) tiles.back()["maps_crc32"] = nullptr;
    }
  m["tiles"] = std::move(tiles);
  return m;
}

}  // namespace

TileSet::TileSet(const TileTerrain& t, int64_t tile, TileFormat format, std::string dir, bool defer_exact_pass)
    : dir_(std::move(dir)) {
  spec_ = make_tile_spec(t, tile, format);
  if (dir_.empty()) invalid("give the tile set's folder");
  identity_ = tileset_identity(t, spec_.grid.tile, format_name(format));
  // A folder holding another set is refused before anything is written in it.
  std::optional<nlohmann::json> old = read_manifest(dir_);
  if (old) {
    const std::string diff = identity_difference(identity_, *old);
    if (!diff.empty())
      invalid("the folder '" + dir_ + "' holds another tile set (" + diff +
              "); choose another folder or remove its manifest.json and tiles");
  }
  make_folder(dir_);
  if (old) {
    manifest_ = std::move(*old);
    spec_.height_min = manifest_["height_range"]["min"].get<double>();
    spec_.height_max = manifest_["height_range"]["max"].get<double>();
    // Fold the last run's journal in: manifest first, then the journal
    // goes (a crash between the two replays it again, to the same effect).
    if (replay_journal(dir_, manifest_) > 0) write_manifest(dir_, manifest_);
    remove_journal(dir_);
    return;
  }
  remove_stale_pending(spec_, dir_);  // what another set's range pass left here belongs to no set
  if (defer_exact_pass && needs_exact_pass(t)) {
    range_pending_ = true;
    return;
  }
  const HeightRange r = tileset_height_range(t, spec_, dir_);
  spec_.height_min = r.min;
  spec_.height_max = r.max;
  remove_journal(dir_);  // a stale one of a removed manifest belongs to no set
  manifest_ = new_manifest(identity_, spec_, r);
  write_manifest(dir_, manifest_);
}

void TileSet::set_height_range(double min, double max) {
  if (!range_pending_) invalid("the tile set in '" + dir_ + "' already has its height range");
  if (!std::isfinite(min) || !std::isfinite(max) || min > max)
    invalid("a tile set's height range must be finite with min <= max, got [" + format_number(min) + ", " +
            format_number(max) + "]");
  spec_.height_min = min;
  spec_.height_max = max;
  remove_journal(dir_);
  manifest_ = new_manifest(identity_, spec_, HeightRange{min, max, "exact"});
  write_manifest(dir_, manifest_);
  range_pending_ = false;
}

void TileSet::check_range_fixed(const char* what) const {
  if (range_pending_)
    invalid(std::string("the tile set in '") + dir_ + "' has no height range yet: give it (the union of its tiles' " +
            "ranges) before " + what);
}

nlohmann::json& TileSet::entry(int32_t col, int32_t row) {
  spec_.grid.check_tile(col, row);
  return manifest_["tiles"][size_t(row) * size_t(spec_.grid.columns()) + size_t(col)];
}

bool TileSet::done(int32_t col, int32_t row) const {
  spec_.grid.check_tile(col, row);
  if (range_pending_) return false;
  const nlohmann::json& e = manifest_["tiles"][size_t(row) * size_t(spec_.grid.columns()) + size_t(col)];
  if (e["crc32"].is_null()) return false;
  auto matches = [&](const std::string& file, uint32_t crc) {
    const std::string path = platform::utf8_of(platform::fs_path(dir_) / platform::fs_path(file));
    std::error_code ec;
    return std::filesystem::is_regular_file(platform::fs_path(path), ec) && file_crc32(path) == crc;
  };
  if (!matches(e["file"].get<std::string>(), e["crc32"].get<uint32_t>())) return false;
  if (!spec_.maps) return true;
  const nlohmann::json c = e.value("maps_crc32", nlohmann::json());
  if (!c.is_array()) return false;
  for (int k = 0; k < FT_MAP_COUNT; ++k)
    if (!matches(map_file_name(spec_, k, col, row), c[size_t(k)].get<uint32_t>())) return false;
  return true;
}

void TileSet::record(int32_t col, int32_t row, const TileCrcs& crcs) {
  check_range_fixed("recording tiles");
  nlohmann::json& e = entry(col, row);
  e["crc32"] = crcs.heights;
  if (spec_.maps) e["maps_crc32"] = crcs.maps;
  append_journal(dir_, col, row, crcs.heights, spec_.maps ? &crcs.maps : nullptr);
}

int64_t TileSet::recorded() const {
  int64_t n = 0;
  for (const nlohmann::json& e : manifest_["tiles"]) n += !e["crc32"].is_null();
  return n;
}

void TileSet::finish() {
  check_range_fixed("finishing");
  const int64_t n = recorded();
  if (n != spec_.grid.count())
    invalid("the tile set in '" + dir_ + "' has " + std::to_string(n) + " of " + std::to_string(spec_.grid.count()) +
            " tiles; write the rest before finishing it");
  if (have_gdal()) {  // without GDAL the set is complete without its mosaic
    write_mosaic_vrt(spec_, dir_);
    manifest_["vrt"] = kMosaicName;
    for (int k = 0; spec_.maps && k < FT_MAP_COUNT; ++k) write_map_vrt(spec_, dir_, k);
  }
  if (!spec_.pending.empty()) remove_pending(spec_, dir_);
  manifest_["complete"] = true;
  write_manifest(dir_, manifest_);
  remove_journal(dir_);
}

}  // namespace ft::tiles
