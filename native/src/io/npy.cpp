// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/npy.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {
namespace {

template <class T>
void convert(const char* src, size_t n, float* dst) {
  for (size_t i = 0; i < n; ++i) {
    T v;
    std::memcpy(&v, src + i * sizeof(T), sizeof(T));
    dst[i] = float(v);
  }
}

// The header is a Python dict literal. Its values are found by hand: the
// std::regex this replaced recursed once per character matched and overflowed
// the stack on a long (crafted) shape tuple.
// Position of the value of `key` (after "key" : and spaces), or npos.
size_t value_of(const std::string& h, const char* key) {
  size_t i = h.find(key);
  if (i == std::string::npos) return i;
  i += std::strlen(key);
  while (i < h.size() && std::isspace(uint8_t(h[i]))) ++i;
  if (i >= h.size() || h[i] != ':') return std::string::npos;
  ++i;
  while (i < h.size() && std::isspace(uint8_t(h[i]))) ++i;
  return i < h.size() ? i : std::string::npos;
}

}  // namespace

NpyArray decode_npy(const std::string& bytes, const std::string& name) {
  auto bad = [&](const std::string& why) { fail(FT_ERR_FORMAT, "'" + name + "' is not a usable .npy file: " + why); };
  if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0) bad("missing the \\x93NUMPY magic");
  const int major = uint8_t(bytes[6]);
  size_t header_len = 0, header_start = 0;
  if (major == 1) {
    header_len = uint8_t(bytes[8]) | (size_t(uint8_t(bytes[9])) << 8);
    header_start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) bad("truncated header");
    header_len = 0;
    for (int i = 0; i < 4; ++i) header_len |= size_t(uint8_t(bytes[8 + i])) << (8 * i);
    header_start = 12;
  } else {
    bad("unknown format version " + std::to_string(major));
  }
  if (header_len > 65536 || header_start + header_len > bytes.size()) bad("truncated header");
  const std::string header = bytes.substr(header_start, header_len);
  // 'descr': '<f4' (byte order, kind, width in bytes).
  size_t i = value_of(header, "'descr'");
  size_t j = i == std::string::npos ? i : i + 3;
  while (j < header.size() && std::isdigit(uint8_t(header[j]))) ++j;
  if (i == std::string::npos || j >= header.size() || header[i] != '\'' || j == i + 3 || header[j] != '\'' ||
      !std::strchr("<>|=", header[i + 1]) || !std::strchr("fiu", header[i + 2]))
    bad("no 'descr'");
  const char order = header[i + 1];
  const char kind = header[i + 2];
  const int width = std::stoi(header.substr(i + 3, std::min<size_t>(j - i - 3, 3)));
  if (order == '>' && width > 1) bad("big-endian data is not supported");
  i = value_of(header, "'fortran_order'");
  const bool fortran = i != std::string::npos && header.compare(i, 4, "True") == 0;
  // 'shape': (h, w) or (n,): the digit runs between the parentheses.
  i = value_of(header, "'shape'");
  const size_t close = i == std::string::npos ? i : header.find(')', i);
  if (close == std::string::npos || header[i] != '(') bad("no 'shape'");
  NpyArray a;
  uint64_t count = 1;
  for (size_t k = i + 1; k < close;) {
    if (!std::isdigit(uint8_t(header[k]))) {
      ++k;
      continue;
    }
    size_t e = k;
    while (e < close && std::isdigit(uint8_t(header[e]))) ++e;
    if (e - k > 9) bad("dimension too large");
    a.shape.push_back(std::stoll(header.substr(k, e - k)));
    count = checked_bytes(count, uint64_t(a.shape.back()));
    k = e;
  }
  if (a.shape.empty() || a.shape.size() > 2) bad("expected a 1D or 2D array");
  size_t elem = 0;
  if (kind == 'f' && (width == 4 || width == 8)) elem = width;
  else if ((kind == 'i' || kind == 'u') && (width == 1 || width == 2 || width == 4 || width == 8)) elem = width;
  else bad(std::string("unsupported element type ") + kind + std::to_string(width));
  const size_t data_start = header_start + header_len;
  if (count > (bytes.size() - data_start) / elem) bad("the data is shorter than its shape says");
  check_allocation(checked_bytes(count, sizeof(float)), "reading '" + name + "'");
  a.values.resize(count);
  const char* src = bytes.data() + data_start;
  float* dst = a.values.data();
  if (kind == 'f') {
    if (width == 4) convert<float>(src, count, dst); else convert<double>(src, count, dst);
  } else if (kind == 'i') {
    if (width == 1) convert<int8_t>(src, count, dst);
    else if (width == 2) convert<int16_t>(src, count, dst);
    else if (width == 4) convert<int32_t>(src, count, dst);
    else convert<int64_t>(src, count, dst);
  } else {
    if (width == 1) convert<uint8_t>(src, count, dst);
    else if (width == 2) convert<uint16_t>(src, count, dst);
    else if (width == 4) convert<uint32_t>(src, count, dst);
    else convert<uint64_t>(src, count, dst);
  }
  if (fortran && a.shape.size() == 2) {
    const size_t rows = size_t(a.shape[0]), cols = size_t(a.shape[1]);
    std::vector<float> c(a.values.size());
    for (size_t r = 0; r < rows; ++r)
      for (size_t col = 0; col < cols; ++col) c[r * cols + col] = a.values[col * rows + r];
    a.values.swap(c);
  }
  return a;
}

NpyArray read_npy(const std::string& path) { return decode_npy(read_file(path), path); }

std::string npy_header(const std::vector<int64_t>& shape) {
  std::string dims;
  for (int64_t d : shape) dims += std::to_string(d) + ", ";
  if (shape.size() == 2) dims.resize(dims.size() - 2);  // (h, w) but (n,) for 1D
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + dims + "), }";
  // Pad so the data starts on a 64-byte boundary, as NumPy does.
  const size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  std::string out = "\x93NUMPY";
  out.push_back('\x01');
  out.push_back('\x00');
  out.push_back(char(header.size() & 0xff));
  out.push_back(char(header.size() >> 8));
  return out + header;
}

void write_npy(const std::string& path, const std::vector<int64_t>& shape, const float* values) {
  size_t count = 1;
  for (int64_t d : shape) count *= size_t(d);
  // The samples go straight from the caller's array: no second copy of a
  // possibly multi-GiB array in memory.
  AtomicFile file(path);
  file.write(npy_header(shape));
  file.write(std::string_view(reinterpret_cast<const char*>(values), count * sizeof(float)));
  file.commit();
}

}  // namespace ft::io
