// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/heightfield_io.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/exr.hpp"
#include "io/npy.hpp"
#include "io/pgm.hpp"
#include "io/raw16.hpp"

namespace ft::io {
namespace {

Heightfield from_npy(const NpyArray& a, const std::string& name) {
  if (a.shape.size() != 2 || a.shape[0] < 1 || a.shape[1] < 1)
    fail(FT_ERR_FORMAT, "'" + name + "' must hold a 2D array for a heightfield");
  Heightfield hf(int32_t(a.shape[1]), int32_t(a.shape[0]));
  std::memcpy(hf.data(), a.values.data(), hf.size() * sizeof(float));
  return hf;
}

// A .npy holds the array alone: its world size goes in "<file>.npy.json" beside it (as RAW16's
// sidecar), written with every .npy heightfield so that no stale one is left from an earlier write.
std::string npy_sidecar_path(const std::string& path) { return path + ".json"; }

void write_npy_heightfield(const Heightfield& hf, const std::string& path) {
  nlohmann::json j = {{"format", "npy"}, {"width", hf.width()}, {"height", hf.height()}};
  if (hf.world_size() > 0) j["world_size"] = hf.world_size();
  AtomicFile npy(path);  // fails early (before the sidecar) on a bad folder
  npy.write(npy_header({hf.height(), hf.width()}));
  npy.write(std::string_view(reinterpret_cast<const char*>(hf.data()), hf.size() * sizeof(float)));
  write_file_atomically(npy_sidecar_path(path), j.dump(2) + "\n");
  npy.commit();
}

Heightfield read_npy_heightfield(const std::string& path) {
  Heightfield hf = from_npy(read_npy(path), path);
  const std::string side = npy_sidecar_path(path);
  std::error_code ec;
  if (!std::filesystem::exists(platform::fs_path(side), ec)) return hf;
  const nlohmann::json j = nlohmann::json::parse(read_file(side), nullptr, false);
  if (j.is_discarded() || !j.is_object())
    fail(FT_ERR_FORMAT, "the sidecar '" + side + "' is not a JSON object");
  // A sidecar of another array (the .npy replaced by another program) must not lend it its world.
  for (const char* key : {"width", "height"})
    if (j.contains(key) && !(j[key].is_number_integer() &&
                             j[key].get<int64_t>() == (key[0] == 'w' ? hf.width() : hf.height())))
      fail(FT_ERR_FORMAT, "the sidecar '" + side + "' describes a " + j.value("width", nlohmann::json()).dump() +
                              " x " + j.value("height", nlohmann::json()).dump() + " array, '" + path + "' holds " +
                              std::to_string(hf.width()) + " x " + std::to_string(hf.height()));
  if (j.contains("world_size")) {
    const double v = j["world_size"].is_number() ? j["world_size"].get<double>() : NAN;
    if (!(std::isfinite(v) && v > 0))
      fail(FT_ERR_FORMAT, "the sidecar '" + side + "' has world_size " + j["world_size"].dump() +
                              " (a positive number is needed)");
    hf.set_world_size(v);
  }
  return hf;
}

std::string unsupported(const std::string& path) {
  return "'" + path + "': unsupported heightfield format (use " + kHeightfieldWriteFormats + ")";
}

bool is_raw16(const std::string& ext) { return ext == ".raw" || ext == ".r16"; }

}  // namespace

GrayImage heightfield_to_image(const Heightfield& hf) {
  const HeightStats s = hf.stats();
  if (!std::isfinite(s.min) || !std::isfinite(s.max)) invalid("the heightfield holds NaN or infinite samples");
  check_allocation(checked_bytes(hf.size(), sizeof(uint16_t)), "the 16-bit image of a heightfield");
  GrayImage img;
  img.width = hf.width();
  img.height = hf.height();
  img.bit_depth = 16;
  img.pixels.resize(hf.size());
  const double range = s.max - s.min;
  const double k = range > 0 ? 65535.0 / range : 0.0;
  const float* z = hf.data();
  for (size_t i = 0; i < hf.size(); ++i) img.pixels[i] = uint16_t(std::lround((z[i] - s.min) * k));
  img.text["fracterra:min"] = format_number(s.min);
  img.text["fracterra:max"] = format_number(s.max);
  img.text["Software"] = "fracterra";
  if (hf.world_size() > 0) img.text["fracterra:world_size"] = format_number(hf.world_size());
  return img;
}

Heightfield image_to_heightfield(const GrayImage& image) {
  double lo = 0.0, hi = 1.0;
  auto a = image.text.find("fracterra:min"), b = image.text.find("fracterra:max");
  if (a != image.text.end() && b != image.text.end()) {
    char* end = nullptr;
    const double l = std::strtod(a->second.c_str(), &end);
    const double h = std::strtod(b->second.c_str(), &end);
    if (std::isfinite(l) && std::isfinite(h) && h >= l) lo = l, hi = h;
  }
  const double full = image.bit_depth == 16 ? 65535.0 : 255.0;
  Heightfield hf(image.width, image.height);
  float* z = hf.data();
  for (size_t i = 0; i < hf.size(); ++i) z[i] = float(lo + (hi - lo) * (image.pixels[i] / full));
  if (auto ws = image.text.find("fracterra:world_size"); ws != image.text.end()) {
    const double v = std::strtod(ws->second.c_str(), nullptr);
    if (std::isfinite(v) && v > 0) hf.set_world_size(v);
  }
  return hf;
}

void write_heightfield(const Heightfield& hf, const std::string& path) {
  const std::string ext = extension_of(path);
  // Every format but .npy stands for heights only: a NaN would become a
  // wrong height (16-bit) or a hole no reader expects (float formats).
  if (ext != ".npy") {
    const float* z = hf.data();
    for (size_t i = 0; i < hf.size(); ++i)
      if (!std::isfinite(z[i]))
        invalid("the heightfield holds NaN or infinite samples (at x " + std::to_string(i % size_t(hf.width())) +
                ", y " + std::to_string(i / size_t(hf.width())) + ")");
  }
  if (ext == ".png") write_png(path, heightfield_to_image(hf));
  else if (ext == ".pgm") write_pgm(path, heightfield_to_image(hf));
  else if (ext == ".npy") write_npy_heightfield(hf, path);
  else if (ext == ".tif" || ext == ".tiff") write_cog(hf, path);
  else if (ext == ".exr") write_exr(hf, path);
  else if (is_raw16(ext)) write_raw16(hf, path);
  else invalid(unsupported(path));
}

Heightfield decode_heightfield(const std::string& bytes, const std::string& extension) {
  if (extension == ".png") return image_to_heightfield(decode_png(bytes));
  if (extension == ".pgm") return image_to_heightfield(decode_pgm(bytes));
  if (extension == ".npy") return from_npy(decode_npy(bytes), "<memory>");
  if (extension == ".exr") return decode_exr(bytes);
  if (is_raw16(extension)) return decode_raw16(bytes, "", "<memory>");
  return decode_gdal(bytes, extension);
}

Heightfield read_heightfield(const std::string& path, NodataPolicy nodata) {
  const std::string ext = extension_of(path);
  if (ext == ".png") return image_to_heightfield(read_png(path));
  if (ext == ".pgm") return image_to_heightfield(read_pgm(path));
  if (ext == ".npy") return read_npy_heightfield(path);
  if (ext == ".exr") return read_exr(path);
  if (is_raw16(ext)) return read_raw16(path);
  return read_gdal(path, nodata);
}

}  // namespace ft::io
