// SPDX-License-Identifier: GPL-3.0-or-later
#include "engines/engine_tiles.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/exr.hpp"
#include "io/png_image.hpp"
#include "io/raw16.hpp"
#include "splat/splat_files.hpp"
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

// The default splat rules' inputs over an engine tile of an eroded set:
// heights, deposits and drainage area read with one sample of margin where
// the set has one (so that slopes at the tile's edges are the whole's), and
// the whole's height range and area (so that a tile's weights are the
// whole's). `ox`, `oy`: where the tile starts in the grown window.
struct TileSplat {
  Heightfield terrain, deposited, area;
  splat::SplatFrame frame;
  int32_t ox = 0, oy = 0;
  splat::SplatInputs inputs() const { return {&terrain, &deposited, &area, &frame}; }
};

TileSplat read_tile_splat(const std::string& dir, const nlohmann::json& m, int64_t x0, int64_t y0, int32_t side) {
  const int64_t width = m["width"].get<int64_t>(), height = m["height"].get<int64_t>();
  const int64_t gx0 = std::max<int64_t>(0, x0 - 1), gy0 = std::max<int64_t>(0, y0 - 1);
  const int64_t gx1 = std::min<int64_t>(width, x0 + side + 1), gy1 = std::min<int64_t>(height, y0 + side + 1);
  const int32_t gw = int32_t(gx1 - gx0), gh = int32_t(gy1 - gy0);
  TileSplat t;
  t.terrain = tiles::read_tileset_window(dir, 0, gx0, gy0, gw, gh);
  t.deposited = tiles::read_tileset_map_window(dir, "deposited", 0, gx0, gy0, gw, gh);
  t.area = tiles::read_tileset_map_window(dir, "drainage_area", 0, gx0, gy0, gw, gh);
  const double lo = m["height_range"]["min"].get<double>(), hi = m["height_range"]["max"].get<double>();
  const double s = m["sample_spacing"].get<double>();
  t.frame = {lo, hi - lo, s * s * double(width - 1) * double(height - 1)};
  t.ox = int32_t(x0 - gx0), t.oy = int32_t(y0 - gy0);
  return t;
}

// Rows [oy, oy + side) and columns [ox, ox + side) of a sample-major array of `n` values per sample.
template <class T>
std::vector<T> crop(const std::vector<T>& v, int32_t width, int32_t n, int32_t ox, int32_t oy, int32_t side) {
  std::vector<T> out(size_t(side) * size_t(side) * size_t(n));
  for (int32_t j = 0; j < side; ++j)
    std::copy_n(v.begin() + std::ptrdiff_t((size_t(oy + j) * size_t(width) + size_t(ox)) * size_t(n)),
                size_t(side) * size_t(n), out.begin() + std::ptrdiff_t(size_t(j) * size_t(side) * size_t(n)));
  return out;
}

// The splat files of engine tile (x, y), named after its heights file; returns them for the sidecar.
nlohmann::json write_tile_splat(Engine e, const TileSplat& t, int32_t side, const std::string& out_dir,
                                const std::string& name, int32_t x, int32_t y) {
  const std::vector<ft_splat_params> layers = splat::default_layers();
  const int32_t n = int32_t(layers.size()), gw = t.terrain.width();
  const std::string xs = std::to_string(x), ys = std::to_string(y);
  if (e == Engine::godot) {
    const Heightfield control = control_map(t.terrain, t.inputs());
    Heightfield tile(side, side);
    std::vector<uint32_t> bits(control.size());  // the control words moved as integers, never as floats
    std::memcpy(bits.data(), control.data(), bits.size() * sizeof(uint32_t));
    const std::vector<uint32_t> cropped = crop(bits, gw, 1, t.ox, t.oy, side);
    std::memcpy(tile.data(), cropped.data(), cropped.size() * sizeof(uint32_t));
    const std::string file = name + "_x" + xs + "_y" + ys + "_control.exr";
    io::write_exr(tile, platform::join_path(out_dir, file), "R");
    return {{"control_file", file}};
  }
  const std::vector<uint16_t> w = crop(splat::splat_weights(t.inputs(), layers.data(), n, 255), gw, n, t.ox, t.oy, side);
  if (e == Engine::unity) {  // one RGBA alphamap per terrain, layers in R, G, B, A
    const std::string file = name + "_" + xs + "_" + ys + "_splat.png";
    splat::write_splat_pngs(platform::join_path(out_dir, file), w, side, side, n, 8);
    return {{"splat_file", file}};
  }
  // Unreal imports one grayscale weight map per layer, tiled by the same _x_y suffix.
  nlohmann::json files = nlohmann::json::object();
  for (int32_t k = 0; k < n; ++k) {
    io::ChannelImage img{side, side, 1, 8, std::vector<uint16_t>(size_t(side) * size_t(side))};
    for (size_t i = 0; i < img.samples.size(); ++i) img.samples[i] = w[i * size_t(n) + size_t(k)];
    const std::string file = name + "_" + layers[size_t(k)].name + "_x" + xs + "_y" + ys + ".png";
    io::write_png_channels(platform::join_path(out_dir, file), img);
    files[layers[size_t(k)].name] = file;
  }
  return {{"weight_files", files}};
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
  // An eroded set with its maps gets the splat maps of the default rules with its tiles.
  const bool with_splat = m.contains("maps") && m.contains("erosion");

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
      if (with_splat)
        files.back().update(write_tile_splat(o.engine, read_tile_splat(set_dir, m, int64_t(x) * step,
                                                                       int64_t(y) * step, side),
                                             side, out_dir, name, x, y));
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
  if (with_splat) {
    nlohmann::json names = nlohmann::json::array();
    for (const auto& l : splat::default_layers()) names.push_back(l.name);
    j["splat_layers"] = names;
  }
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
