// Wraps the optional C progress callback. report() is called between stages
// of a long computation (never from worker threads), and throws
// FT_ERR_CANCELLED when the caller asks to stop, so the partly made result is
// destroyed by ordinary unwinding.
#pragma once

#include "core/error.hpp"

namespace ft {

class Progress {
 public:
  Progress() = default;
  Progress(ft_progress_fn fn, void* user) : fn_(fn), user_(user) {}

  void report(double fraction) const {
    if (fn_ && fn_(user_, fraction) != 0) fail(FT_ERR_CANCELLED, "cancelled by the progress callback");
  }

 private:
  ft_progress_fn fn_ = nullptr;
  void* user_ = nullptr;
};

}  // namespace ft
