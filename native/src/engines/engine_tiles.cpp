#include "engines/engine_tiles.hpp"

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/exr.hpp"
#include "io/png_image.hpp"
#include "io/raw16.hpp"
#include "tiles/manifest.hpp"
#include "tiles/tile_writer.hpp"
#include "tiles/tileset_reader.hpp"

namespace ft::engines {
namespace {

// Samples per tile side each engine takes.
bool takes(Engine e, int32_t n, int32_t region_size) {
  switch (e) {
    case Engine::unity: return n >= 33 && n <= 4097 && ((n - 1) & (n - 2)) == 0;  // 2^k + 1
    case Engine::unreal: return n >= 8 && n <= 8192;  // any; the importer fits the whole to its components
    default: return n == region_size;                 // Terrain3D: one region per file
  }
}

// How far apart the tiles start: Unity's tiles share their edge samples.
int32_t step_of(Engine e, int32_t n) { return e == Engine::unity ? n - 1 : n; }

// The engine tile sizes that divide a set of width x height samples, largest first.
std::vector<int32_t> dividing_sizes(Engine e, int64_t width, int64_t height, int32_t region_size) {
  std::vector<int32_t> sizes;
  for (int32_t n = 8193; n >= 8; --n)
    if (takes(e, n, region_size) && (width - 1) % step_of(e, n) == 0 && (height - 1) % step_of(e, n) == 0)
      sizes.push_back(n);
  return sizes;
}

}  // namespace

int32_t engine_tile_side(const EngineOptions& o, int64_t width, int64_t height, int64_t preferred_step) {
  check_region_size(o.region_size);
  const std::vector<int32_t> sizes = dividing_sizes(o.engine, width, height, o.region_size);
  const std::string set = std::to_string(width) + " x " + std::to_string(height);
  if (o.side != 0) {
    if (std::find(sizes.begin(), sizes.end(), o.side) != sizes.end()) return o.side;
    std::string list;
    for (size_t i = 0; i < sizes.size() && i < 8; ++i) list += (i ? ", " : "") + std::to_string(sizes[i]);
    invalid(std::string("a ") + engine_name(o.engine) + " tile of " + std::to_string(o.side) +
            " samples does not cut a " + set + " set" +
            (o.engine == Engine::unity  ? " (Unity takes 2^n + 1 in [33, 4097], tiles sharing edges)"
             : o.engine == Engine::godot ? " (Terrain3D: the region size)"
                                         : "") +
            (list.empty() ? std::string("; no size does") : "; sizes that do: " + list));
  }
  for (int32_t n : sizes)
    if (preferred_step > 0 && step_of(o.engine, n) == preferred_step) return n;
  const int32_t cap = o.engine == Engine::unity ? 1025 : o.engine == Engine::unreal ? 1024 : o.region_size;
  for (int32_t n : sizes)
    if (n <= cap) return n;
  invalid(std::string("no ") + engine_name(o.engine) + " tile size cuts a " + set + " set" +
          (o.engine == Engine::godot ? " into regions of " + std::to_string(o.region_size) +
                                           " (width - 1 and height - 1 must be multiples of the region size)"
                                     : std::string(" (width - 1 and height - 1 must be multiples of the tile step)")));
}

namespace {

std::string tile_name(Engine e, const std::string& name, int32_t x, int32_t y) {
  const std::string xs = std::to_string(x), ys = std::to_string(y);
  switch (e) {
    case Engine::unity: return name + "_" + xs + "_" + ys + ".raw";
    case Engine::unreal: return name + "_x" + xs + "_y" + ys + ".png";
    default: return name + "_x" + xs + "_y" + ys + ".exr";
  }
}

}  // namespace

nlohmann::json write_engine_tiles(const std::string& set_dir, const std::string& out_dir, const EngineOptions& o,
                                  const std::string& name) {
  const std::optional<nlohmann::json> found = tiles::read_manifest(set_dir);
  if (!found || !found->value("complete", false))
    invalid("'" + set_dir + "' holds no finished tile set: write it first (fracterra tiles)");
  const nlohmann::json& m = *found;
  const int64_t width = m["width"].get<int64_t>(), height = m["height"].get<int64_t>();
  const int32_t side = engine_tile_side(o, width, height, m["tile"].get<int64_t>());
  const int32_t step = step_of(o.engine, side);
  const int32_t columns = int32_t((width - 1) / step), rows = int32_t((height - 1) / step);
  const double lo = m["height_range"]["min"].get<double>(), hi = m["height_range"]["max"].get<double>();
  const double spacing = m["sample_spacing"].get<double>();
  std::filesystem::create_directories(platform::fs_path(out_dir));

  nlohmann::json files = nlohmann::json::array();
  for (int32_t y = 0; y < rows; ++y)
    for (int32_t x = 0; x < columns; ++x) {
      const Heightfield hf = tiles::read_tileset_window(set_dir, 0, int64_t(x) * step, int64_t(y) * step, side, side);
      const std::string file = tile_name(o.engine, name, x, y);
      const std::string path = platform::join_path(out_dir, file);
      const std::string what = std::string(engine_name(o.engine)) + " tile " + file;
      if (o.engine == Engine::unity) {
        io::write_file_atomically(path, io::encode_raw16(tiles::quantise16(hf, lo, hi, what)));
      } else if (o.engine == Engine::unreal) {
        GrayImage img{side, side, 16, tiles::quantise16(hf, lo, hi, what), {{"Software", "fracterra"}}};
        io::write_png(path, img);
      } else {
        io::write_exr(hf, path, "R");
      }
      // Where the tile's first sample lies, in the engine's metres (row y of
      // the set goes along the engine's second horizontal axis, as for one file).
      files.push_back({{"file", file},
                       {"x", x},
                       {"y", y},
                       {"position", {{"x", double(x) * step * spacing}, {"z", double(y) * step * spacing}}}});
    }

  const double range = hi - lo, tile_size = spacing * (side - 1);
  nlohmann::json j = {{"engine", engine_name(o.engine)},
                      {"tile_set", platform::file_name_of(set_dir)},
                      {"tile_samples", side},
                      {"tile_step", step},
                      {"columns", columns},
                      {"rows", rows},
                      {"min", lo},
                      {"max", hi},
                      {"height_range", range},
                      {"sample_spacing", spacing},
                      {"units", "metres (1 world unit = 1 m)"},
                      {"files", files}};
  switch (o.engine) {
    case Engine::unity:
      j["unity"] = {{"depth", "Bit 16"},
                    {"byte_order", "Windows"},
                    {"resolution", side},
                    {"flip_vertically", false},
                    {"tiles_x", columns},
                    {"tiles_z", rows},
                    {"terrain_size", {{"x", tile_size}, {"y", range}, {"z", tile_size}}},
                    {"position_y", lo}};
      break;
    case Engine::unreal: {
      const double z = unreal_z_scale(range);
      j["unreal"] = {{"scale", {{"x", spacing * 100.0}, {"y", spacing * 100.0}, {"z", z}}},
                     {"location_z_cm", unreal_location_z_cm(lo, z)},
                     {"resolution", {{"x", int64_t(columns) * side}, {"y", int64_t(rows) * side}}},
                     {"file_pattern", name + "_x0_y0.png"},
                     {"z_scale_formula", "height_range_m x 100 x 128 / 65535"}};
      break;
    }
    case Engine::godot: {
      std::vector<std::string> textures;
      for (const auto& l : splat::default_layers()) textures.push_back(l.name);
      j["godot"] = {{"region_size", o.region_size},
                    {"vertex_spacing", spacing},
                    {"height_scale", 1.0},
                    {"height_offset", 0.0},
                    {"texture_ids", textures}};
      break;
    }
  }
  io::write_file_atomically(
      platform::join_path(out_dir, std::string(engine_name(o.engine)) + ".json"),
      j.dump(2) + "\n");
  return j;
}

}  // namespace ft::engines
