// SPDX-License-Identifier: GPL-3.0-or-later
// Heightfields as OpenEXR (Debian libopenexr-dev, the reference library of
// the format): one FLOAT channel "Y", ZIP compression (lossless), so the
// round trip is exact to the bit. The world size rides in the header as the
// double attribute "fracterra:world_size". Reading takes "Y", else "Z",
// else "R", else the first channel (HALF and UINT are converted to float).
#pragma once

#include <string>

#include "core/heightfield.hpp"

namespace ft::io {

// Atomic. `channel` names the one channel: "Y" by default; Godot's EXR loader
// takes a single "R" channel as a one-channel float image (FORMAT_RF).
void write_exr(const Heightfield& hf, const std::string& path, const char* channel = "Y");
Heightfield read_exr(const std::string& path);
Heightfield decode_exr(const std::string& bytes);

}  // namespace ft::io
