// SPDX-License-Identifier: GPL-3.0-or-later
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

// The part [start, start + span] of an outer progress, as a Progress of its
// own (0..1): a stage of a longer computation. Outlives what it is given to.
class ProgressPart {
 public:
  ProgressPart(const Progress& outer, double start, double span) : outer_(outer), start_(start), span_(span) {}
  ProgressPart(const ProgressPart&) = delete;
  ProgressPart& operator=(const ProgressPart&) = delete;
  Progress progress() const { return Progress(&call, const_cast<ProgressPart*>(this)); }

 private:
  static int call(void* self, double f) {
    auto* s = static_cast<ProgressPart*>(self);
    try {
      s->outer_.report(s->start_ + s->span_ * f);
    } catch (const Error&) {
      return 1;
    }
    return 0;
  }
  const Progress& outer_;
  double start_, span_;
};

}  // namespace ft
