// SPDX-License-Identifier: GPL-3.0-or-later
#include "splat/splat_files.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/png_image.hpp"

namespace ft::splat {

std::vector<SplatFile> write_splat_pngs(const std::string& path, const std::vector<uint16_t>& weights,
                                        int32_t width, int32_t height, int32_t layers, int bit_depth) {
  if (io::extension_of(path) != ".png") invalid("splat maps are written as .png, got '" + path + "'");
  if (bit_depth != 8 && bit_depth != 16) invalid("splat maps are 8- or 16-bit, got " + std::to_string(bit_depth));
  const size_t samples = size_t(width) * size_t(height);
  if (weights.size() != samples * size_t(layers)) invalid("splat weights do not match width x height x layers");
  std::vector<SplatFile> files;
  for (int32_t first = 0, index = 0; first < layers; first += 4, ++index) {
    SplatFile f;
    f.path = index == 0 ? path
                        : platform::sibling_path(path, std::string("_") + std::to_string(index) + ".png");
    f.first_layer = first;
    f.layers = std::min(4, layers - first);
    io::ChannelImage im{width, height, 4, bit_depth, std::vector<uint16_t>(samples * 4, 0)};
    for (size_t i = 0; i < samples; ++i)
      for (int32_t c = 0; c < f.layers; ++c) im.samples[i * 4 + size_t(c)] = weights[i * size_t(layers) + size_t(first + c)];
    io::write_png_channels(f.path, im);
    files.push_back(f);
  }
  return files;
}

void write_color_png(const std::string& path, const std::vector<float>& rgb, int32_t width, int32_t height) {
  io::ChannelImage im{width, height, 3, 8, std::vector<uint16_t>(rgb.size())};
  for (size_t i = 0; i < rgb.size(); ++i) im.samples[i] = uint16_t(std::lround(std::clamp(rgb[i], 0.0f, 1.0f) * 255.0f));
  io::write_png_channels(path, im);
}

}  // namespace ft::splat
