// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the fuzz harnesses: a reader that turns the fuzzer's bytes into
// fields, and the rule every harness enforces: a reader either succeeds or
// throws ft::Error; anything else (another exception, a crash, a sanitizer
// report) is a bug. The harnesses are plain functions, so the same file is
// built once with libFuzzer (FT_FUZZ=ON, clang) and once with a small driver
// that replays the corpus and the regression inputs under ctest (any compiler).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/polyline_io.hpp"

namespace ft::fuzz {

// Memory cap the harnesses run under: small enough that every accepted
// request is fast, large enough for the seed files (the largest is 65 x 65).
inline constexpr uint64_t kFuzzMemoryCap = uint64_t{4} << 20;

// Takes fixed-size values from the front of the input; past the end it gives zeros.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : p_(data), n_(size) {}
  template <class T>
  T take() {
    T v{};
    const size_t k = n_ < sizeof(T) ? n_ : sizeof(T);
    std::memcpy(&v, p_, k);
    p_ += k;
    n_ -= k;
    return v;
  }
  void take_into(void* dst, size_t size) {
    std::memset(dst, 0, size);
    const size_t k = n_ < size ? n_ : size;
    std::memcpy(dst, p_, k);
    p_ += k;
    n_ -= k;
  }
  std::string rest() {
    std::string s(reinterpret_cast<const char*>(p_), n_);
    p_ += n_;
    n_ = 0;
    return s;
  }
  size_t left() const { return n_; }

 private:
  const uint8_t* p_;
  size_t n_;
};

[[noreturn]] inline void bug(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what.c_str());
  std::abort();
}

// Runs a reader; ft::Error is an accepted outcome (bad input, clear message)
// but its message must say something, and FT_ERR_INTERNAL is a bug.
template <class F>
void expect_ok_or_error(F&& f) {
  try {
    f();
  } catch (const ft::Error& e) {
    if (e.status() == FT_ERR_INTERNAL) bug(std::string("internal error: ") + e.what());
    if (e.what()[0] == '\0') bug("an error without a message");
  }
}

// The image readers' promise: a consistent 8- or 16-bit image that converts
// to a heightfield of its size.
template <class Decode>
void check_image_reader(const uint8_t* data, size_t size, Decode decode) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  expect_ok_or_error([&] {
    const ft::GrayImage img = decode(bytes);
    if (img.width < 1 || img.height < 1 || img.pixels.size() != size_t(img.width) * size_t(img.height))
      bug("decoded image size does not match its pixels");
    if (img.bit_depth != 8 && img.bit_depth != 16) bug("bit depth neither 8 nor 16");
    const ft::Heightfield hf = ft::io::image_to_heightfield(img);
    if (hf.width() != img.width || hf.height() != img.height) bug("heightfield size differs from the image");
  });
}

// The polyline readers' promise: whatever they accept is a consistent set
// with no empty line, and it survives a write and re-read exactly.
template <class Decode, class Encode>
void check_polyline_reader(const uint8_t* data, size_t size, Decode decode, Encode encode) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  expect_ok_or_error([&] {
    const ft::PolylineSet s = decode(text);
    if (s.offsets.empty() || s.offsets.front() != 0 || s.offsets.back() != s.vertex_count() ||
        s.radii.size() != s.points.size())
      bug("inconsistent polyline set");
    for (int64_t i = 0; i < s.line_count(); ++i)
      if (s.line_end(i) <= s.line_begin(i)) bug("empty polyline kept");
    const ft::PolylineSet t = decode(encode(s));
    if (t.points != s.points || t.radii != s.radii || t.offsets != s.offsets)
      bug("write + read does not give back the same polylines");
  });
}

}  // namespace ft::fuzz
