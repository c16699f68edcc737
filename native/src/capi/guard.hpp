// The extern "C" boundary: every export runs its body through guarded(),
// which records success or the error message for ft_last_error() and makes
// sure no exception crosses into C or Python.
#pragma once

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

// Checks an output handle pointer and clears what it points to.
template <class T>
void reset_out(T** out) {
  check_not_null("out", out);
  *out = nullptr;
}

}  // namespace ft::capi
