// SPDX-License-Identifier: GPL-3.0-or-later
// NumPy .npy arrays (format 1.0-3.0): 2D (heightfields) or 1D (profiles).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ft::io {

struct NpyArray {
  std::vector<int64_t> shape;  // C order
  std::vector<float> values;   // converted to float32
};

// Reads little-endian float32/float64/(u)int8/16/32/64 arrays, C or Fortran
// order (Fortran is transposed into C order).
NpyArray decode_npy(const std::string& bytes, const std::string& name = "<memory>");
NpyArray read_npy(const std::string& path);
// The magic, version and header of a float32 C-order array of `shape` (its samples follow).
std::string npy_header(const std::vector<int64_t>& shape);
// Writes a float32 C-order array atomically.
void write_npy(const std::string& path, const std::vector<int64_t>& shape, const float* values);

}  // namespace ft::io
