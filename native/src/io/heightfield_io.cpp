// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/heightfield_io.hpp"

#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "core/memory.hpp"
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
  else if (ext == ".npy") write_npy(path, {hf.height(), hf.width()}, hf.data());
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
  if (ext == ".npy") return from_npy(read_npy(path), path);
  if (ext == ".exr") return read_exr(path);
  if (is_raw16(ext)) return read_raw16(path);
  return read_gdal(path, nodata);
}

}  // namespace ft::io
