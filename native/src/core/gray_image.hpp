// SPDX-License-Identifier: GPL-3.0-or-later
// A grayscale raster in memory: what PNG and PGM files hold and what the
// clouds image is made as. A plain value type of its own so that analysis/
// can make images without including a file format (io/ reads and writes it).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ft {

struct GrayImage {
  int32_t width = 0, height = 0;
  int bit_depth = 16;             // 8 or 16
  std::vector<uint16_t> pixels;   // row-major, row 0 = top of the image
  std::map<std::string, std::string> text;  // key/value pairs (PNG tEXt chunks)
};

}  // namespace ft
