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

}  // namespace ft::fuzz
