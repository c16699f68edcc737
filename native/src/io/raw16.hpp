// SPDX-License-Identifier: GPL-3.0-or-later
// Heightfields as RAW16 for game engines (Unity's "RAW 16-bit, byte order
// Windows", Unreal's .r16): unsigned 16-bit little-endian samples, row by row
// from the first row (the top of a PNG) with no header, normalised so that
// 0 is the lowest height and 65535 the highest. A sidecar JSON, "<file>.json"
// (terrain.r16 -> terrain.r16.json), holds what the samples cannot:
//   {"format": "raw16", "byte_order": "little", "width": W, "height": H,
//    "min": lo, "max": hi, "height_range": hi - lo, "world_size": S}
// Reading without the sidecar takes a square of side sqrt(bytes / 2) with
// heights 0..1, as engines do.
#pragma once

#include <string>
#include <vector>

#include "core/heightfield.hpp"

namespace ft::io {

// Writes both files, each atomically (the sidecar first: a raw file is never
// beside a sidecar that does not describe it, unless the second rename fails).
void write_raw16(const Heightfield& hf, const std::string& path);
Heightfield read_raw16(const std::string& path);
// `sidecar` is the JSON text, or "" for none.
Heightfield decode_raw16(const std::string& bytes, const std::string& sidecar, const std::string& name);
std::string raw16_sidecar_path(const std::string& path);
// The file's bytes: each code as unsigned 16-bit little-endian, in order.
std::string encode_raw16(const std::vector<uint16_t>& codes);

}  // namespace ft::io
