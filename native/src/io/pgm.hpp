// SPDX-License-Identifier: GPL-3.0-or-later
// Netpbm graymaps: binary P5 (8- or 16-bit) and plain P2. fracterra records
// the real height range in a "# fracterra-range MIN MAX" comment line.
#pragma once

#include <string>

#include "io/png_image.hpp"

namespace ft::io {

GrayImage decode_pgm(const std::string& bytes, const std::string& name = "<memory>");
GrayImage read_pgm(const std::string& path);
// Writes P5 atomically; text entries "fracterra:min"/"fracterra:max" become
// the range comment.
void write_pgm(const std::string& path, const GrayImage& image);

}  // namespace ft::io
