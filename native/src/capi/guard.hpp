// SPDX-License-Identifier: GPL-3.0-or-later
// The extern "C" boundary: every export runs its body through guarded(),
// which records success or the error message for ft_last_error() and makes
// sure no exception crosses into C or Python.
#pragma once

#include <cstring>
#include <new>
#include <string>

#include "core/error.hpp"

namespace ft::capi {

void set_last_error(const std::string& message);
void clear_last_error();

template <class F>
ft_status guarded(F&& body) noexcept {
  try {
    clear_last_error();
    body();
    return FT_OK;
  } catch (const Error& e) {
    set_last_error(e.what());
    return e.status();
  } catch (const std::bad_alloc&) {
    set_last_error("out of memory");
    return FT_ERR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    set_last_error(std::string("internal error: ") + e.what());
    return FT_ERR_INTERNAL;
  } catch (...) {
    set_last_error("internal error: unknown exception");
    return FT_ERR_INTERNAL;
  }
}

// Result structs start with a struct_size that the caller sets: a caller built
// against this or a later ABI gets every field this library has, one built
// against an earlier 2.x the fields its smaller struct holds. `first_size` is
// the struct's size in the ABI that introduced it (2.0).
template <class T>
void write_result(T* out, T result, size_t first_size, const char* name) {
  check_not_null("out", out);
  if (out->struct_size < first_size)
    invalid(std::string(name) + ".struct_size is " + std::to_string(out->struct_size) + ", expected at least " +
            std::to_string(first_size) + " (set it to sizeof(" + name + ") before the call)");
  const size_t n = out->struct_size < sizeof(T) ? out->struct_size : sizeof(T);
  result.struct_size = out->struct_size;
  std::memcpy(static_cast<void*>(out), &result, n);
}

// Checks an output handle pointer and clears what it points to.
template <class T>
void reset_out(T** out) {
  check_not_null("out", out);
  *out = nullptr;
}

}  // namespace ft::capi
