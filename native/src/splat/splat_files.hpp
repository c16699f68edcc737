// SPDX-License-Identifier: GPL-3.0-or-later
// Splat maps as RGBA PNGs, four layers to a file, as Unity's alphamaps and
// Unreal's weight-map import take them: layers 0-3 in `path`, 4-7 in
// "<stem>_1.png", and so on; a last file with fewer layers has zeros in its
// unused channels. The layers' weights of all files together sum to the
// total (255 for 8-bit, 65535 for 16-bit) at every sample.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ft::splat {

struct SplatFile {
  std::string path;
  int32_t first_layer = 0, layers = 0;  // layers first_layer .. first_layer + layers - 1 in R, G, B, A
};

// `weights` sample-major (splat_weights()); bit_depth 8 or 16.
std::vector<SplatFile> write_splat_pngs(const std::string& path, const std::vector<uint16_t>& weights,
                                        int32_t width, int32_t height, int32_t layers, int bit_depth);

// An 8-bit RGB PNG of a colour map (sRGB 0..1, three floats per sample).
void write_color_png(const std::string& path, const std::vector<float>& rgb, int32_t width, int32_t height);

}  // namespace ft::splat
