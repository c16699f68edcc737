// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/raw16.hpp"

#include <nlohmann/json.hpp>

#include <cfloat>
#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"

namespace ft::io {

std::string raw16_sidecar_path(const std::string& path) { return path + ".json"; }

std::string encode_raw16(const std::vector<uint16_t>& codes) {
  std::string bytes(codes.size() * 2, '\0');
  for (size_t i = 0; i < codes.size(); ++i) {
    bytes[2 * i] = char(codes[i] & 0xff);
    bytes[2 * i + 1] = char(codes[i] >> 8);
  }
  return bytes;
}

void write_raw16(const Heightfield& hf, const std::string& path) {
  const GrayImage img = heightfield_to_image(hf);  // normalised 16-bit, checks NaN and the cap
  const HeightStats s = hf.stats();
  nlohmann::json j = {{"format", "raw16"},     {"byte_order", "little"}, {"width", hf.width()},
                      {"height", hf.height()}, {"min", s.min},           {"max", s.max},
                      {"height_range", s.max - s.min}};
  if (hf.world_size() > 0) j["world_size"] = hf.world_size();
  AtomicFile raw(path);  // fails early (before the sidecar) on a bad folder
  raw.write(encode_raw16(img.pixels));
  write_file_atomically(raw16_sidecar_path(path), j.dump(2) + "\n");
  raw.commit();
}

Heightfield decode_raw16(const std::string& bytes, const std::string& sidecar, const std::string& name) {
  int64_t w = 0, h = 0;
  double lo = 0.0, hi = 1.0, world = 0.0;
  if (!sidecar.empty()) {
    nlohmann::json j = nlohmann::json::parse(sidecar, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("width") || !j.contains("height") ||
        !j["width"].is_number_integer() || !j["height"].is_number_integer())
      fail(FT_ERR_FORMAT, "the sidecar of '" + name + "' is not JSON with integer \"width\" and \"height\"");
    w = j["width"].get<int64_t>();
    h = j["height"].get<int64_t>();
    if (j.contains("min") && j.contains("max") && j["min"].is_number() && j["max"].is_number()) {
      lo = j["min"].get<double>();
      hi = j["max"].get<double>();
      // Heights are floats: a range beyond FLT_MAX would make them infinite.
      if (!(std::fabs(lo) <= FLT_MAX) || !(std::fabs(hi) <= FLT_MAX) || hi < lo)
        fail(FT_ERR_FORMAT, "the sidecar of '" + name + "' has min " + format_number(lo) + " and max " +
                                format_number(hi) + " (both finite floats, min <= max, are needed)");
    }
    if (j.contains("world_size") && j["world_size"].is_number()) world = j["world_size"].get<double>();
  } else {
    w = h = int64_t(std::llround(std::sqrt(double(bytes.size() / 2))));
  }
  if (w < 1 || h < 1 || w > (1 << 20) || h > (1 << 20) || uint64_t(w) * uint64_t(h) * 2 != bytes.size())
    fail(FT_ERR_FORMAT, "'" + name + "' has " + std::to_string(bytes.size()) + " bytes; " + std::to_string(w) +
                            " x " + std::to_string(h) + " 16-bit samples need " +
                            std::to_string(checked_bytes(uint64_t(w), uint64_t(h), 2)) +
                            (sidecar.empty() ? " (no sidecar JSON: a square was assumed)" : ""));
  Heightfield hf{int32_t(w), int32_t(h)};
  float* z = hf.data();
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  for (size_t i = 0; i < hf.size(); ++i)
    z[i] = float(lo + (hi - lo) * (double(b[2 * i] | (b[2 * i + 1] << 8)) / 65535.0));
  if (std::isfinite(world) && world > 0) hf.set_world_size(world);
  return hf;
}

Heightfield read_raw16(const std::string& path) {
  const std::string side = raw16_sidecar_path(path);
  std::error_code ec;
  const std::string sidecar = std::filesystem::exists(platform::fs_path(side), ec) ? read_file(side) : std::string();
  return decode_raw16(read_file(path), sidecar, path);
}

}  // namespace ft::io
