// SPDX-License-Identifier: GPL-3.0-or-later
// Grayscale PNG through libpng: 8- or 16-bit, with tEXt key/value pairs
// (fracterra records the real height range there).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/gray_image.hpp"

namespace ft::io {

// How hard libpng works: the default (deflate level 3, libpng's adaptive
// choice of row filter) suits a single file; `fast` (level 1, the Up filter
// alone) is for bulk writers such as tile sets, where encoding dominates.
enum class PngEffort { normal, fast };

// Writes atomically; 8-bit images use the low byte range 0..255 of `pixels`.
void write_png(const std::string& path, const GrayImage& image, PngEffort effort = PngEffort::normal);
// Writes an 8-bit RGB image (width * height * 3 bytes, row 0 on top) atomically.
void write_png_rgb(const std::string& path, int32_t width, int32_t height, const uint8_t* rgb);
// A PNG of 1 (gray), 2 (gray + alpha), 3 (RGB) or 4 (RGBA) channels at 8 or
// 16 bits, `samples` interleaved (width * height * channels values, row 0 on
// top; 8-bit values 0..255). Written atomically. For weight maps and colour
// maps, whose channels are data, not a picture to be turned into luma.
struct ChannelImage {
  int32_t width = 0, height = 0, channels = 0, bit_depth = 0;
  std::vector<uint16_t> samples;
};
void write_png_channels(const std::string& path, const ChannelImage& image);
// Reads a gray, gray + alpha, RGB or RGBA PNG of 8 or 16 bits as it is stored
// (palette and sub-byte images are refused).
ChannelImage read_png_channels(const std::string& path);
// Reads gray, gray+alpha, palette or RGB(A) PNGs of any depth; colour is
// turned into luma. 8-bit images come back with bit_depth 8 (values 0..255).
GrayImage read_png(const std::string& path);
// Same from bytes in memory (for fuzzing and tests).
GrayImage decode_png(const std::string& bytes, const std::string& name = "<memory>");

}  // namespace ft::io
