#include "tiles/manifest.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
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
    return nlohmann::json::parse(io::read_file(path));
  } catch (const nlohmann::json::exception& e) {
    fail(FT_ERR_IO, "'" + path + "' is not a tile set manifest (" + e.what() + "); remove it or choose another folder");
  }
}

void write_manifest(const std::string& dir, const nlohmann::json& m) {
  io::write_file_atomically(path_in(dir, kManifestName), m.dump(1) + "\n");
}

void append_journal(const std::string& dir, int32_t col, int32_t row, uint32_t crc) {
  const std::string path = path_in(dir, kJournalName);
  const std::string line = nlohmann::json{{"column", col}, {"row", row}, {"crc32", crc}}.dump() + "\n";
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) fail(FT_ERR_IO, "cannot open '" + path + "': " + std::strerror(errno));
  // One write of a short line: O_APPEND puts it whole at the end.
  const bool ok = ::write(fd, line.data(), line.size()) == ssize_t(line.size()) && ::fdatasync(fd) == 0;
  const int err = errno;
  ::close(fd);
  if (!ok) fail(FT_ERR_IO, "cannot append to '" + path + "': " + std::strerror(err));
}

int64_t replay_journal(const std::string& dir, nlohmann::json& m) {
  const std::string path = path_in(dir, kJournalName);
  if (!std::filesystem::exists(path)) return 0;
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
    tiles[size_t(row * columns + col)]["crc32"] = e["crc32"].get<uint32_t>();
    ++applied;
  }
  return applied;
}

void remove_journal(const std::string& dir) {
  std::error_code ec;
  std::filesystem::remove(path_in(dir, kJournalName), ec);
  if (ec) fail(FT_ERR_IO, "cannot remove '" + path_in(dir, kJournalName) + "': " + ec.message());
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

}  // namespace ft::tiles
