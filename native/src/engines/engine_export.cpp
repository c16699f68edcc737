// SPDX-License-Identifier: GPL-3.0-or-later
#include "engines/engine_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/exr.hpp"
#include "io/heightfield_io.hpp"
#include "io/raw16.hpp"

namespace ft::engines {
namespace {

std::string control_path(const std::string& out) {
  return platform::sibling_path(out, "_control.exr");
}

}  // namespace

Heightfield control_map(const Heightfield& hf, const splat::SplatInputs& maps) {
  const auto layers = splat::default_layers();
  const int32_t n = int32_t(layers.size());
  splat::SplatInputs in = maps;
  in.terrain = &hf;
  const std::vector<float> f = splat::layer_fractions(in, layers.data(), n);
  Heightfield control(hf.width(), hf.height());
  for (size_t i = 0; i < hf.size(); ++i) {
    const float* w = f.data() + i * size_t(n);
    int32_t a = 0, b = -1;
    for (int32_t k = 1; k < n; ++k)
      if (w[k] > w[a]) a = k;
    for (int32_t k = 0; k < n; ++k)
      if (k != a && (b < 0 || w[k] > w[b])) b = k;
    const double pair = double(w[a]) + (b >= 0 ? w[b] : 0.0f);
    const uint32_t blend = b >= 0 && pair > 0 ? uint32_t(std::lround(255.0 * w[b] / pair)) : 0u;
    const uint32_t bits = terrain3d_control(uint32_t(a), uint32_t(b >= 0 ? b : a), blend);
    std::memcpy(&control.data()[i], &bits, sizeof bits);  // Terrain3D keeps the uint32 in a float's bits
  }
  return control;
}

const char* engine_extension(Engine e) {
  switch (e) {
    case Engine::unity: return ".raw";
    case Engine::unreal: return ".png";
    default: return ".exr";
  }
}

Heightfield resample(const Heightfield& hf, int32_t width, int32_t height) {
  if (hf.width() < 2 || hf.height() < 2 || width < 2 || height < 2)
    invalid("resampling needs at least 2 x 2 samples on both sides");
  Heightfield out(width, height);
  out.set_world_size(hf.world_size());
  out.set_georef(hf.georef());
  const double sx = double(hf.width() - 1) / (width - 1), sy = double(hf.height() - 1) / (height - 1);
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < height; ++y) {
    const double v = y * sy;
    const int32_t y0 = std::min(int32_t(v), hf.height() - 2);
    const double fy = v - y0;
    for (int32_t x = 0; x < width; ++x) {
      const double u = x * sx;
      const int32_t x0 = std::min(int32_t(u), hf.width() - 2);
      const double fx = u - x0;
      const double top = hf.at(x0, y0) * (1 - fx) + hf.at(x0 + 1, y0) * fx;
      const double bottom = hf.at(x0, y0 + 1) * (1 - fx) + hf.at(x0 + 1, y0 + 1) * fx;
      out.at(x, y) = float(top * (1 - fy) + bottom * fy);
    }
  }
  return out;
}

std::pair<int32_t, int32_t> engine_size(const Heightfield& hf, const EngineOptions& o) {
  if (o.engine == Engine::godot) {
    if (o.side) return {o.side, o.side};
    return {engine_side(o.engine, hf.width(), o.region_size), engine_side(o.engine, hf.height(), o.region_size)};
  }
  if (hf.width() != hf.height())
    invalid(std::string(o.engine == Engine::unity ? "Unity" : "Unreal") + " terrains are square; this one is " +
            std::to_string(hf.width()) + " x " + std::to_string(hf.height()));
  const int32_t side = o.side ? o.side : engine_side(o.engine, hf.width(), o.region_size);
  return {side, side};
}

void check_engine_output(const EngineOptions& o, const std::string& out) {
  const std::vector<int32_t> sides = engine_sides(o.engine, o.region_size);  // checks the region size
  if (o.side != 0 && std::find(sides.begin(), sides.end(), o.side) == sides.end()) {
    std::string s;
    for (int32_t v : sides) s += (s.empty() ? "" : ", ") + std::to_string(v);
    invalid(std::string("the size for ") + engine_name(o.engine) + " must be one of " + s + ", got " +
            std::to_string(o.side));
  }
  const std::string ext = io::extension_of(out);
  const bool ok_ext = o.engine == Engine::unity ? (ext == ".raw" || ext == ".r16") : ext == engine_extension(o.engine);
  if (!ok_ext)
    invalid(std::string("the engine ") + engine_name(o.engine) + " takes " +
            (o.engine == Engine::unity ? ".raw or .r16" : engine_extension(o.engine)) + " files: give NAME" +
            engine_extension(o.engine) + ", got '" + out + "'");
}

nlohmann::json write_for_engine(const Heightfield& given, const std::string& out, const EngineOptions& o,
                                const splat::SplatInputs& maps) {
  check_engine_output(o, out);
  const auto [w, h] = engine_size(given, o);
  const bool resampled = w != given.width() || h != given.height();
  // At the same size, resample() is an exact copy (Heightfield has no copy constructor).
  Heightfield hf = resample(given, w, h);
  if (hf.world_size() <= 0) hf.set_world_size(10.0);
  const HeightStats s = hf.stats();
  const double range = s.max - s.min, spacing = hf.world_size() / (w - 1);
  nlohmann::json j = {{"engine", engine_name(o.engine)},
                      {"file", platform::file_name_of(out)},
                      {"width", w},
                      {"height", h},
                      {"min", s.min},
                      {"max", s.max},
                      {"height_range", range},
                      {"world_size", hf.world_size()},
                      {"units", "metres (1 world unit = 1 m)"},
                      {"resampled_from", resampled ? nlohmann::json::array({given.width(), given.height()})
                                                   : nlohmann::json(nullptr)}};
  switch (o.engine) {
    case Engine::unity:
      io::write_raw16(hf, out);
      j["format"] = "raw16";
      j["byte_order"] = "little";
      j["unity"] = {{"depth", "Bit 16"},
                    {"byte_order", "Windows"},
                    {"resolution", w},
                    {"flip_vertically", false},
                    {"terrain_size", {{"x", hf.world_size()}, {"y", range}, {"z", spacing * (h - 1)}}},
                    {"position_y", s.min}};
      break;
    case Engine::unreal: {
      io::write_heightfield(hf, out);  // 16-bit PNG, 0..65535 over the range
      const double z = unreal_z_scale(range);
      const UnrealLayout l = unreal_layout(w);
      j["format"] = "png16";
      j["unreal"] = {{"scale", {{"x", spacing * 100.0}, {"y", spacing * 100.0}, {"z", z}}},
                     {"location_z_cm", unreal_location_z_cm(s.min, z)},
                     {"section_size_quads", l.quads_per_section},
                     {"sections_per_component", l.sections_per_component},
                     {"components", l.components},
                     {"z_scale_formula", "height_range_m x 100 x 128 / 65535"}};
      break;
    }
    case Engine::godot: {
      io::write_exr(hf, out, "R");
      const std::string control = control_path(out);
      // The maps follow the terrain to the engine's size.
      Heightfield deposited, area;
      splat::SplatInputs at_size = maps;
      if (resampled && maps.deposited) at_size.deposited = &(deposited = resample(*maps.deposited, w, h));
      if (resampled && maps.drainage_area) at_size.drainage_area = &(area = resample(*maps.drainage_area, w, h));
      io::write_exr(control_map(hf, at_size), control, "R");
      std::vector<std::string> textures;
      for (const auto& l : splat::default_layers()) textures.push_back(l.name);
      j["format"] = "exr";
      j["godot"] = {{"region_size", o.region_size},
                    {"vertex_spacing", spacing},
                    {"height_scale", 1.0},
                    {"height_offset", 0.0},
                    {"control_file", platform::file_name_of(control)},
                    {"texture_ids", textures}};
      break;
    }
  }
  // Unity's RAW16 sidecar is this same file: it keeps raw16's fields.
  io::write_file_atomically(out + ".json", j.dump(2) + "\n");
  return j;
}

}  // namespace ft::engines
