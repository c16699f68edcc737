// SPDX-License-Identifier: GPL-3.0-or-later
// The whole-grid diamond-square refiner: one (2^levels + 1)^2 grid refined
// in place, stage by stage, as in MidPointFM2D. Its parts live in the files
// named after what they do:
//   refiner.cpp         set-up (corners, reference grid), the stage loop,
//                       bands and progress, border points, periodic wrap;
//   midpoint.cpp        a stage of plain midpoint displacement (square and
//                       diamond steps fused row by row);
//   additions.cpp       a stage of Feder's successive random additions (two
//                       sweeps, then delta g added to the grid's points);
//   midpoint_steps.cpp  the arithmetic of a point, shared with windows.
// Internal to terrain/: callers use diamond_square() (diamond_square.hpp).
#pragma once

#include <algorithm>
#include <cstdint>

#include "core/heightfield.hpp"
#include "core/rng.hpp"
#include "terrain/diamond_square.hpp"

namespace ft::terrain::detail {

class Refiner {
 public:
  Refiner(const DiamondSquareConfig& c, Heightfield& hf);
  void run();

 private:
  float& at(int x, int y) { return x_[size_t(y) * w_ + x]; }
  float* row(int y) { return x_ + size_t(y) * w_; }

  // refiner.cpp
  void first_touch();
  void place_corners();
  void place_reference();
  double stage_samples(int s) const;
  int addition_count(int origin, int step) const;
  template <class RowsFn>
  void in_bands(int rows, int per_row, RowsFn&& rows_fn);
  void square_one_row(int s, int j, int big, int half, float delta, float* g);
  void diamond_one_row(int s, int y, int big, int half, float delta, float* g);
  void diamond_row(int y, int x0, int count, int big, int half, float delta, const float* g);
  float edge_point(int x, int y, int half);
  void wrap_edges();

  // midpoint.cpp
  void fused_stage(int s, int big, int half, float square_delta, float diamond_delta);

  // additions.cpp
  void additions_stage(int s, int big, int half, float square_delta, float diamond_delta);
  void square_step(int s, int big, int half, float delta);
  void diamond_step(int s, int big, int half, float delta);
  void add_to_grid(int level, int origin, int step, float delta, Stream stream);
  bool pinned(int x, int y) const { return ref_step_ != 0 && x % ref_step_ == 0 && y % ref_step_ == 0; }

  const DiamondSquareConfig& c_;
  const int n_, w_;
  float* x_;
  int threads_;

  // Small passes run on one thread: waking a team costs more than they do,
  // and on a busy machine every barrier can wait a whole time slice for a
  // descheduled worker. (Output never depends on the thread count.)
  static constexpr size_t kMinParallelPoints = size_t(1) << 16;
  int threads_for(size_t points) const { return points >= kMinParallelPoints ? threads_ : 1; }
  int ref_step_ = 0;
  double done_ = 0, total_ = 0;
};

// Each step runs over its rows in bands of about this many samples, with a
// progress report between bands: a level-14 terrain's last stage is ~2.7e8
// samples (seconds of work), a band a few milliseconds, so a cancel lands
// within a fraction of a second. Bands only split a row loop, and no row
// reads what another row of the same step writes, so the output is the same.
inline constexpr int64_t kBandSamples = int64_t(1) << 20;

// Calls rows_fn(r0, r1) for consecutive row ranges covering 0..rows-1,
// each about kBandSamples samples, reporting progress after each.
template <class RowsFn>
void Refiner::in_bands(int rows, int per_row, RowsFn&& rows_fn) {
  const int band = int(std::max<int64_t>(1, kBandSamples / std::max(1, per_row)));
  for (int r0 = 0; r0 < rows; r0 += band) {
    const int r1 = std::min(rows, r0 + band);
    rows_fn(r0, r1);
    done_ += double(r1 - r0) * double(per_row);
    c_.progress.report(std::min(1.0, done_ / total_));
  }
}

}  // namespace ft::terrain::detail
