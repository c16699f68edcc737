// SPDX-License-Identifier: GPL-3.0-or-later
// A stage of Voss midpoint displacement on the whole grid (see refiner.hpp).
#include <atomic>
#include <exception>
#include <vector>

#include <omp.h>

#include "terrain/refiner.hpp"

namespace ft::terrain::detail {

// The square and diamond steps fused row by row: square row j, then the
// diamond points of that centre row, then those of the grid row above it,
// whose square rows are both done. A few rows stay in cache instead of two
// sweeps over the whole grid (at 8193^2 the grid is 268 MB). Every point
// reads exactly the values it reads in the two-sweep order (diamond points
// never read each other), so the output is bit-identical. Additions change
// old points between the steps, so they keep the two sweeps (additions.cpp).
//
// One parallel region per stage, each thread on its contiguous share of
// square rows, with a single barrier before the grid rows at the shares'
// starts: the bands of in_bands (one region and barrier per band, 256 of
// them in the last stage at 8193^2) made every thread wait for the slowest
// one 256 times, and on a busy machine for a descheduled one each time.
// Progress is reported, and a cancel taken, by the calling thread (the
// team's master) between its bands; the others stop at their next row.
void Refiner::fused_stage(int s, int big, int half, float square_delta, float diamond_delta) {
  const int cells = n_ / big, per_row = 3 * cells + 1;
  const int band = int(std::max<int64_t>(1, kBandSamples / per_row));
  const int team = threads_for(size_t(cells) * size_t(cells) * 3);
  const double stage_start = done_, stage = double(cells) * double(per_row);
  std::atomic<bool> stop{false};
  std::exception_ptr cancelled;
#pragma omp parallel num_threads(team)
  {
    std::vector<float> g(size_t(cells) + 5);
    const int parts = omp_get_num_threads(), id = omp_get_thread_num();
    const int b0 = int(int64_t(cells) * id / parts), b1 = int(int64_t(cells) * (id + 1) / parts);
    for (int j = b0; j < b1 && !stop.load(std::memory_order_relaxed); ++j) {
      square_one_row(s, j, big, half, square_delta, g.data());
      diamond_one_row(s, half + j * big, big, half, diamond_delta, g.data());
      if (j > b0) diamond_one_row(s, j * big, big, half, diamond_delta, g.data());
      if (id == 0 && (j - b0 + 1) % band == 0) {
        try {  // the master's share stands for the team's progress
          c_.progress.report(std::min(1.0, (stage_start + stage * double(j - b0 + 1) / double(b1 - b0)) / total_));
        } catch (...) {
          cancelled = std::current_exception();
          stop.store(true, std::memory_order_relaxed);
        }
      }
    }
    // The grid row at the start of each part needs the square row of the
    // part before it.
#pragma omp barrier
    if (!stop.load(std::memory_order_relaxed) && b0 < b1 && !(b0 == 0 && c_.periodic))
      diamond_one_row(s, b0 * big, big, half, diamond_delta, g.data());
  }
  if (cancelled) std::rethrow_exception(cancelled);
  done_ = stage_start + stage;
  c_.progress.report(std::min(1.0, done_ / total_));
  std::vector<float> g(size_t(cells) + 5);
  if (c_.periodic) {
    diamond_one_row(s, 0, big, half, diamond_delta, g.data());  // wraps to the last square row
    wrap_edges();
  } else {
    diamond_one_row(s, n_, big, half, diamond_delta, g.data());
  }
}

}  // namespace ft::terrain::detail
