// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/pgm.hpp"

#include <cctype>
#include <sstream>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {

GrayImage decode_pgm(const std::string& bytes, const std::string& name) {
  auto bad = [&](const std::string& why) { fail(FT_ERR_FORMAT, "'" + name + "' is not a usable PGM file: " + why); };
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '2')) bad("missing the P5/P2 magic");
  const bool binary = bytes[1] == '5';
  GrayImage img;
  size_t pos = 2;
  // Header tokens, skipping white space and comments (keeping ours).
  auto token = [&]() -> long long {
    for (;;) {
      while (pos < bytes.size() && std::isspace(uint8_t(bytes[pos]))) ++pos;
      if (pos < bytes.size() && bytes[pos] == '#') {
        const size_t end = bytes.find('\n', pos);
        std::istringstream c(bytes.substr(pos + 1, end == std::string::npos ? std::string::npos : end - pos - 1));
        std::string tag, lo, hi;
        if (c >> tag >> lo && tag == "fracterra-world-size") img.text["fracterra:world_size"] = lo;
        else if (c >> hi && tag == "fracterra-range") {
          img.text["fracterra:min"] = lo;
          img.text["fracterra:max"] = hi;
        }
        pos = end == std::string::npos ? bytes.size() : end + 1;
        continue;
      }
      break;
    }
    long long v = 0;
    int digits = 0;
    while (pos < bytes.size() && std::isdigit(uint8_t(bytes[pos])) && digits < 10) {
      v = v * 10 + (bytes[pos++] - '0');
      ++digits;
    }
    if (digits == 0 || digits >= 10) bad("malformed header");
    return v;
  };
  const long long w = token(), h = token(), maxval = token();
  if (w <= 0 || h <= 0 || w > (1 << 20) || h > (1 << 20)) bad("bad size");
  if (maxval <= 0 || maxval > 65535) bad("maxval must be 1..65535");
  const size_t count = size_t(w) * size_t(h);
  check_allocation(checked_bytes(count, 2), "reading '" + name + "'");
  img.width = int32_t(w);
  img.height = int32_t(h);
  img.bit_depth = maxval > 255 ? 16 : 8;
  img.pixels.resize(count);
  const double scale = (img.bit_depth == 16 ? 65535.0 : 255.0) / double(maxval);
  if (binary) {
    ++pos;  // the single white-space byte after maxval
    const size_t bpp = maxval > 255 ? 2 : 1;
    if (bytes.size() < pos || (bytes.size() - pos) / bpp < count) bad("the pixel data is truncated");
    for (size_t i = 0; i < count; ++i) {
      const unsigned v = bpp == 2 ? (uint8_t(bytes[pos + 2 * i]) << 8) | uint8_t(bytes[pos + 2 * i + 1])
                                  : uint8_t(bytes[pos + i]);
      if (v > maxval) bad("a pixel exceeds maxval");
      img.pixels[i] = uint16_t(v * scale + 0.5);
    }
  } else {
    for (size_t i = 0; i < count; ++i) {
      const long long v = token();
      if (v > maxval) bad("a pixel exceeds maxval");
      img.pixels[i] = uint16_t(double(v) * scale + 0.5);
    }
  }
  return img;
}

GrayImage read_pgm(const std::string& path) { return decode_pgm(read_file(path), path); }

void write_pgm(const std::string& path, const GrayImage& image) {
  std::string out = "P5\n";
  auto lo = image.text.find("fracterra:min"), hi = image.text.find("fracterra:max");
  if (lo != image.text.end() && hi != image.text.end())
    out += "# fracterra-range " + lo->second + " " + hi->second + "\n";
  if (auto ws = image.text.find("fracterra:world_size"); ws != image.text.end())
    out += "# fracterra-world-size " + ws->second + "\n";
  out += std::to_string(image.width) + " " + std::to_string(image.height) + "\n" +
         (image.bit_depth == 16 ? "65535" : "255") + "\n";
  const size_t n = image.pixels.size();
  if (image.bit_depth == 16) {
    for (size_t i = 0; i < n; ++i) {
      out.push_back(char(image.pixels[i] >> 8));
      out.push_back(char(image.pixels[i] & 0xff));
    }
  } else {
    for (size_t i = 0; i < n; ++i) out.push_back(char(image.pixels[i] > 255 ? 255 : image.pixels[i]));
  }
  write_file_atomically(path, out);
}

}  // namespace ft::io
