// Heightfields to and from files, chosen by extension:
//   .png  16-bit grayscale, normalised to 0..65535, real min/max in tEXt
//         ("fracterra:min", "fracterra:max");
//   .pgm  16-bit P5, range in a comment;
//   .npy  float32, exact.
// Reading restores real units where the range was recorded; otherwise
// samples are in 0..1.
#pragma once

#include <string>

#include "core/heightfield.hpp"
#include "io/png_image.hpp"

namespace ft {

void write_heightfield(const Heightfield& hf, const std::string& path);
Heightfield read_heightfield(const std::string& path);
// The normalised 16-bit image of a heightfield (with the range recorded).
GrayImage heightfield_to_image(const Heightfield& hf);
Heightfield image_to_heightfield(const GrayImage& image);
// Bytes in memory, with the format given by extension (".png", ".pgm", ".npy").
Heightfield decode_heightfield(const std::string& bytes, const std::string& extension);

}  // namespace ft
