#include "tiles/manifest.hpp"

#include <zlib.h>

#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "terrain/terrain_params.hpp"

namespace ft {
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

std::string path_in(const std::string& dir, const char* name) { return (std::filesystem::path(dir) / name).string(); }

}  // namespace

nlohmann::json terrain_identity(const ft_terrain_params& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const ft_param_info& row : terrain_param_table().rows) {
    if ((row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) || row.count != 1 ||
        row.type == FT_PARAM_POINTER || row.type == FT_PARAM_STRING || row.type == FT_PARAM_CALLBACK)
      continue;
    if (std::strcmp(row.name, "threads") == 0) continue;  // output never depends on it
    if (std::strcmp(row.name, "method") != 0 && !(row.methods & (uint64_t(1) << p.method))) continue;
    j[row.name] = value_of(row, &p);
  }
  if (p.reference != nullptr && (p.method == FT_TERRAIN_MIDPOINT || p.method == FT_TERRAIN_ADDITIONS)) {
    const size_t n = size_t(p.reference_size) * size_t(p.reference_size);
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(p.reference), uInt(n * sizeof(float)));
    j["reference"] = {{"size", p.reference_size}, {"crc32", uint32_t(crc)}};
  }
  if (p.falloff == FT_FALLOFF_CUSTOM && p.falloff_mask != nullptr) {
    // Another mask makes another terrain: its tiles must not be reused.
    const size_t n = size_t(p.falloff_mask_width) * size_t(p.falloff_mask_height);
    const uLong crc =
        crc32_z(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(p.falloff_mask), n * sizeof(float));
    j["falloff_mask"] = {{"width", p.falloff_mask_width}, {"height", p.falloff_mask_height}, {"crc32", uint32_t(crc)}};
  }
  return j;
}

std::optional<nlohmann::json> read_manifest(const std::string& dir) {
  const std::string path = path_in(dir, kManifestName);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    return nlohmann::json::parse(read_file(path));
  } catch (const nlohmann::json::exception& e) {
    fail(FT_ERR_IO, "'" + path + "' is not a tile set manifest (" + e.what() + "); remove it or choose another folder");
  }
}

void write_manifest(const std::string& dir, const nlohmann::json& m) {
  write_file_atomically(path_in(dir, kManifestName), m.dump(1) + "\n");
}

std::string identity_difference(const nlohmann::json& wanted, const nlohmann::json& existing) {
  if (!existing.is_object() || existing.value("format", "") != "fracterra-tileset")
    return "the folder's manifest.json is not a fracterra tile set manifest";
  for (const char* key : {"tile", "tile_format"}) {
    if (existing.value(key, nlohmann::json()) != wanted[key])
      return std::string(key) + ": " + wanted[key].dump() + " here, " + existing.value(key, nlohmann::json()).dump() +
             " in the folder";
  }
  const nlohmann::json& a = wanted["terrain"];
  const nlohmann::json b = existing.value("terrain", nlohmann::json::object());
  for (auto it = a.begin(); it != a.end(); ++it)
    if (!b.contains(it.key()) || b[it.key()] != it.value())
      return it.key() + ": " + it.value().dump() + " here, " + (b.contains(it.key()) ? b[it.key()].dump() : "none") +
             " in the folder";
  for (auto it = b.begin(); it != b.end(); ++it)
    if (!a.contains(it.key())) return it.key() + ": none here, " + it.value().dump() + " in the folder";
  return "";
}

}  // namespace ft
