// SPDX-License-Identifier: GPL-3.0-or-later
// Errors inside the library are exceptions carrying an ft_status; the C ABI
// (capi/guard.hpp) turns them into a status code plus ft_last_error().
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "fracterra/core.h"

namespace ft {

class Error : public std::runtime_error {
 public:
  Error(ft_status status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  ft_status status() const noexcept { return status_; }

 private:
  ft_status status_;
};

[[noreturn]] inline void fail(ft_status status, const std::string& message) {
  throw Error(status, message);
}

[[noreturn]] inline void invalid(const std::string& message) {
  throw Error(FT_ERR_INVALID_ARGUMENT, message);
}

// Parameter checks that name the parameter and the allowed range, so every
// message says what was wrong and what is allowed.
inline std::string format_number(double v) {
  if (std::isnan(v)) return "NaN";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

inline void check_range(const char* name, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    invalid(std::string(name) + " must be in [" + format_number(lo) + ", " + format_number(hi) +
            "], got " + format_number(value));
}

inline void check_positive(const char* name, double value) {
  if (!(value > 0.0) || !std::isfinite(value))
    invalid(std::string(name) + " must be a finite number > 0, got " + format_number(value));
}

inline void check_finite(const char* name, double value) {
  if (!std::isfinite(value))
    invalid(std::string(name) + " must be finite, got " + format_number(value));
}

inline void check_int_range(const char* name, long long value, long long lo, long long hi) {
  if (value < lo || value > hi)
    invalid(std::string(name) + " must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
            ", got " + std::to_string(value));
}

// Parameter structs start with their own size (filled by the *_init call)
// so that the ABI can grow; a struct of another size was not made for this
// library (or was never initialised).
inline void check_struct_size(uint32_t got, size_t want, const char* name) {
  if (got != want)
    invalid(std::string(name) + ".struct_size is " + std::to_string(got) + ", expected " + std::to_string(want) +
            " (fill it with " + name + "_init, or set it to sizeof(" + name + "))");
}

template <class T>
void check_not_null(const char* name, const T* p) {
  if (p == nullptr) invalid(std::string(name) + " must not be NULL");
}

}  // namespace ft
