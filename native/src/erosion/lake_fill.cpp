// SPDX-License-Identifier: GPL-3.0-or-later
#include "erosion/lake_fill.hpp"

#include <algorithm>

namespace ft::erosion {

double LakeFill::fill(int32_t exit, double load) {
  if (!(load > 0)) return 0;
  const float surface = surface_[exit];
  // The lake: the exit and, through the donor lists, every cell under the
  // same surface that drains to it.
  cells_.clear();
  todo_.assign(1, exit);
  while (!todo_.empty()) {
    const int32_t v = todo_.back();
    todo_.pop_back();
    cells_.push_back(v);
    for (int32_t k = graph_.donor_start[v]; k < graph_.donor_start[v + 1]; ++k) {
      const int32_t d = graph_.donors[k];
      if (in_lake_of(d, exit)) todo_.push_back(d);
    }
  }
  // Lowest first (ties by index, so the order is the same on every run).
  std::sort(cells_.begin(), cells_.end(), [this](int32_t a, int32_t b) { return z_[a] != z_[b] ? z_[a] < z_[b] : a < b; });
  // The floor: the level where the cells below it hold `load`. Raising the
  // lowest j + 1 cells to the next cell's height (or the surface) holds
  // (j + 1) x that height - their heights' sum.
  const double depth = load / cell_;  // the load as a depth over one cell
  const size_t count = cells_.size();
  double sum = 0, floor = surface;
  for (size_t j = 0; j < count; ++j) {
    sum += z_[cells_[j]];
    const double next = j + 1 < count ? std::min<double>(z_[cells_[j + 1]], surface) : double(surface);
    if (double(j + 1) * next - sum >= depth || j + 1 == count || next >= surface) {
      floor = std::min<double>(surface, (depth + sum) / double(j + 1));
      break;
    }
  }
  const float level = float(floor);
  double laid = 0;
  for (const int32_t c : cells_) {
    if (!(z_[c] < level)) break;  // sorted: the rest stand above the floor
    laid += double(level) - z_[c];
    z_[c] = level;
  }
  return std::min(load, laid * cell_);
}

}  // namespace ft::erosion
