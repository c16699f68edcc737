// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/manifest.hpp"

#include <zlib.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "erosion/erosion_params.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "terrain/terrain_method.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::tiles {
namespace {

nlohmann::json value_of(const ft_param_info& row, const void* p) {
  const char* at = static_cast<const char*>(p) + row.offset;
  switch (row.type) {
    case FT_PARAM_UINT64: {
      uint64_t v;
      std::memcpy(&v, at, sizeof v);
      return v;
    }
    case FT_PARAM_INT64: {
      int64_t v;
      std::memcpy(&v, at, sizeof v);
      return v;
    }
    case FT_PARAM_FLOAT: case FT_PARAM_DOUBLE: return read_number(row, p);
    case FT_PARAM_BOOL: return read_number(row, p) != 0;
    case FT_PARAM_ENUM: {
      const int v = int(read_number(row, p));
      for (int i = 0; i < row.enum_count; ++i)
        if (row.enum_items[i].value == v) return row.enum_items[i].name;
      return v;
    }
    default: return int64_t(read_number(row, p));
  }
}

uint32_t crc_of_floats(const float* v, size_t n) {
  return uint32_t(crc32_z(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(v), n * sizeof(float)));
}

}  // namespace

nlohmann::json terrain_identity(const ft_terrain_params& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const ft_param_info& row : terrain::terrain_param_table().rows) {
    if ((row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) || row.count != 1 ||
        row.type == FT_PARAM_POINTER || row.type == FT_PARAM_STRING || row.type == FT_PARAM_CALLBACK)
      continue;
    if (std::strcmp(row.name, "threads") == 0) continue;  // output never depends on it
    if (std::strcmp(row.name, "method") != 0 && !(row.methods & (uint64_t(1) << p.method))) continue;
    j[row.name] = value_of(row, &p);
  }
  if (p.reference != nullptr && terrain::terrain_method(p.method).reference) {
    const size_t n = size_t(p.reference_size) * size_t(p.reference_size);
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(p.reference), uInt(n * sizeof(float)));
    j["reference"] = {{"size", p.reference_size}, {"crc32", uint32_t(crc)}};
  }
  if (p.falloff == FT_FALLOFF_CUSTOM && p.falloff_mask != nullptr) {
    // Another mask makes another terrain: its tiles must not be reused.
    const size_t n = size_t(p.falloff_mask_width) * size_t(p.falloff_mask_height);
    j["falloff_mask"] = {{"width", p.falloff_mask_width},
                         {"height", p.falloff_mask_height},
                         {"crc32", crc_of_floats(p.falloff_mask, n)}};
  }
  return j;
}

nlohmann::json erosion_identity(const TileTerrain& t) {
  if (!t.erodes()) return nullptr;
  const std::string preset = pipeline::erosion_preset_name(t.preset);
  // What the pipeline erodes with: the preset over the given settings (the
  // presets need no terrain to be fitted to).
  const ft_erosion_params e = pipeline::erosion_settings(t.has_erosion ? &t.erosion : nullptr, preset, Heightfield());
  nlohmann::json j = {{"preset", preset.empty() ? "none" : preset}};
  for (const ft_param_info& row : erosion::erosion_param_table().rows) {
    if ((row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) || row.count != 1 ||
        row.type == FT_PARAM_POINTER || row.type == FT_PARAM_STRING || row.type == FT_PARAM_CALLBACK)
      continue;
    // The pipeline's own rules set these (threads, the torus of a terrain that tiles).
    if (std::strcmp(row.name, "threads") == 0 || std::strcmp(row.name, "periodic") == 0) continue;
    j[row.name] = value_of(row, &e);
  }
  if (e.erosion_mask)
    j["erosion_mask"] = {{"width", e.erosion_mask_width},
                         {"height", e.erosion_mask_height},
                         {"crc32", crc_of_floats(e.erosion_mask, size_t(e.erosion_mask_width) * e.erosion_mask_height)}};
  if (e.rain_map)
    j["rain_map"] = {{"width", e.rain_map_width},
                     {"height", e.rain_map_height},
                     {"crc32", crc_of_floats(e.rain_map, size_t(e.rain_map_width) * e.rain_map_height)}};
  return j;
}

nlohmann::json tileset_identity(const TileTerrain& t, int64_t tile, const std::string& format) {
  nlohmann::json j = {{"terrain", terrain_identity(t.terrain)}, {"tile", tile}, {"tile_format", format}};
  if (t.erodes()) j["erosion"] = erosion_identity(t);
  if (t.maps) j["maps"] = kMapNames;
  return j;
}

namespace {

// What the readers of a manifest take from it, by type and range, so that a
// damaged or hand-edited file is refused here with the field named instead
// of failing inside the JSON library (its type errors are internal errors).
std::string manifest_problem(const nlohmann::json& m) {
  if (!m.is_object()) return "not a JSON object";
  if (m.value("format", nlohmann::json()) != "fracterra-tileset") return "\"format\" is not \"fracterra-tileset\"";
  auto count = [&](const nlohmann::json& o, const char* key, int64_t lo) {
    return o.contains(key) && o[key].is_number_integer() && o[key].get<int64_t>() >= lo &&
           o[key].get<int64_t>() <= int64_t(INT32_MAX);
  };
  for (const char* key : {"tile", "width", "height", "columns", "rows"})
    if (!count(m, key, 1)) return std::string("\"") + key + "\" is not an integer in [1, 2^31)";
  if (!m.contains("terrain") || !m["terrain"].is_object()) return "\"terrain\" is not an object";
  if (!m.contains("sample_spacing") || !m["sample_spacing"].is_number()) return "\"sample_spacing\" is not a number";
  const nlohmann::json* range = m.contains("height_range") ? &m["height_range"] : nullptr;
  if (!range || !range->is_object() || !range->contains("min") || !range->contains("max") ||
      !(*range)["min"].is_number() || !(*range)["max"].is_number())
    return "\"height_range\" has no numbers \"min\" and \"max\"";
  if (m.contains("complete") && !m["complete"].is_boolean()) return "\"complete\" is not true or false";
  const auto columns = m["columns"].get<int64_t>(), rows = m["rows"].get<int64_t>();
  if (!m.contains("tiles") || !m["tiles"].is_array() || int64_t(m["tiles"].size()) != columns * rows)
    return "\"tiles\" is not a list of columns x rows tiles";
  for (const nlohmann::json& t : m["tiles"])
    if (!t.is_object() || !t.contains("file") || !t["file"].is_string() || !count(t, "x0", 0) ||
        !count(t, "y0", 0) || !t.contains("crc32") || !(t["crc32"].is_null() || t["crc32"].is_number_unsigned()) ||
        (t["crc32"].is_number_unsigned() && t["crc32"].get<uint64_t>() > UINT32_MAX))
      return "a tile is not an object with \"file\", \"x0\", \"y0\" and \"crc32\"";
  if (m.contains("maps")) {
    if (!m["maps"].is_array() || m["maps"].size() != kMapNames.size()) return "\"maps\" is not the list of maps";
    for (const nlohmann::json& t : m["tiles"]) {
      const nlohmann::json c = t.value("maps_crc32", nlohmann::json());
      if (c.is_null()) continue;
      if (!c.is_array() || c.size() != kMapNames.size()) return "a tile's \"maps_crc32\" is not one CRC-32 per map";
      for (const nlohmann::json& v : c)
        if (!v.is_number_unsigned() || v.get<uint64_t>() > UINT32_MAX) return "a tile's \"maps_crc32\" is not one CRC-32 per map";
    }
  }
  return "";
}

}  // namespace

nlohmann::json parse_manifest(const std::string& text, const std::string& path) {
  const nlohmann::json m = nlohmann::json::parse(text, nullptr, false);
  const std::string problem = m.is_discarded() ? "not JSON" : manifest_problem(m);
  if (!problem.empty())
    fail(FT_ERR_IO, "'" + path + "' is not a tile set manifest (" + problem + "); remove it or choose another folder");
  return m;
}

std::optional<nlohmann::json> read_manifest(const std::string& dir) {
  const std::string path = platform::join_path(dir, kManifestName);
  if (!std::filesystem::exists(platform::fs_path(path))) return std::nullopt;
  return parse_manifest(io::read_file(path), path);
}

void write_manifest(const std::string& dir, const nlohmann::json& m) {
  io::write_file_atomically(platform::join_path(dir, kManifestName), m.dump(1) + "\n");
}

void append_journal(const std::string& dir, int32_t col, int32_t row, uint32_t crc,
                    const std::array<uint32_t, FT_MAP_COUNT>* maps) {
  const std::string path = platform::join_path(dir, kJournalName);
  nlohmann::json e = {{"column", col}, {"row", row}, {"crc32", crc}};
  if (maps) e["maps_crc32"] = *maps;
  const std::string line = e.dump() + "\n";
  const std::string why = platform::append_synced(path, line);
  if (!why.empty()) fail(FT_ERR_IO, "cannot append to '" + path + "': " + why);
}

int64_t replay_journal(const std::string& dir, nlohmann::json& m) {
  const std::string path = platform::join_path(dir, kJournalName);
  if (!std::filesystem::exists(platform::fs_path(path))) return 0;
  const std::string text = io::read_file(path);
  nlohmann::json& tiles = m["tiles"];
  const int64_t columns = m.value("columns", int64_t(0)), rows = m.value("rows", int64_t(0));
  int64_t applied = 0;
  for (size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1) {
    const nlohmann::json e = nlohmann::json::parse(text.begin() + std::ptrdiff_t(at), text.begin() + std::ptrdiff_t(end),
                                                   nullptr, false);
    if (!e.is_object() || !e.contains("column") || !e.contains("row") || !e.contains("crc32") ||
        !e["column"].is_number_integer() || !e["row"].is_number_integer() || !e["crc32"].is_number_unsigned())
      continue;  // not a line this writes: skipped, the tile is redone
    const int64_t col = e["column"].get<int64_t>(), row = e["row"].get<int64_t>();
    if (col < 0 || col >= columns || row < 0 || row >= rows) continue;
    nlohmann::json& tile = tiles[size_t(row * columns + col)];
    if (m.contains("maps")) {  // a set with maps: a line without its maps' CRCs is not this set's
      const nlohmann::json c = e.value("maps_crc32", nlohmann::json());
      if (!c.is_array() || c.size() != kMapNames.size()) continue;
      tile["maps_crc32"] = c;
    }
    tile["crc32"] = e["crc32"].get<uint32_t>();
    ++applied;
  }
  return applied;
}

void remove_journal(const std::string& dir) {
  std::error_code ec;
  std::filesystem::remove(platform::fs_path(platform::join_path(dir, kJournalName)), ec);
  if (ec) fail(FT_ERR_IO, "cannot remove '" + platform::join_path(dir, kJournalName) + "': " + ec.message());
}

namespace {

// The first key whose value differs between two flat objects, in words.
std::string object_difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& prefix) {
  for (auto it = a.begin(); it != a.end(); ++it)
    if (!b.contains(it.key()) || b[it.key()] != it.value())
      return prefix + it.key() + ": " + it.value().dump() + " here, " +
             (b.contains(it.key()) ? b[it.key()].dump() : "none") + " in the folder";
  for (auto it = b.begin(); it != b.end(); ++it)
    if (!a.contains(it.key())) return prefix + it.key() + ": none here, " + it.value().dump() + " in the folder";
  return "";
}

}  // namespace

std::string identity_difference(const nlohmann::json& wanted, const nlohmann::json& existing) {
  if (!existing.is_object() || existing.value("format", "") != "fracterra-tileset")
    return "the folder's manifest.json is not a fracterra tile set manifest";
  for (const char* key : {"tile", "tile_format"}) {
    if (existing.value(key, nlohmann::json()) != wanted[key])
      return std::string(key) + ": " + wanted[key].dump() + " here, " + existing.value(key, nlohmann::json()).dump() +
             " in the folder";
  }
  if (std::string d = object_difference(wanted["terrain"], existing.value("terrain", nlohmann::json::object()), "");
      !d.empty())
    return d;
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json ea = wanted.value("erosion", nlohmann::json()), eb = existing.value("erosion", nlohmann::json());
  if (ea.is_null() != eb.is_null() || (!ea.is_null() && ea.value("preset", "") != eb.value("preset", "")))
    return "erosion: " + (ea.is_null() ? std::string("none") : "preset " + ea.value("preset", std::string("none"))) +
           " here, " + (eb.is_null() ? std::string("none") : "preset " + eb.value("preset", std::string("none"))) +
           " in the folder";
  if (std::string d = object_difference(ea.is_null() ? none : ea, eb.is_null() ? none : eb, "erosion "); !d.empty())
    return d;
  const bool ma = wanted.contains("maps"), mb = existing.contains("maps");
  if (ma != mb)
    return std::string("maps: ") + (ma ? "kept" : "none") + " here, " + (mb ? "kept" : "none") + " in the folder";
  return "";
}

}  // namespace ft::tiles
