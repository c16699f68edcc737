// SPDX-License-Identifier: GPL-3.0-or-later
// Multiple-flow drainage area (see multiple_flow.hpp).
#include "erosion/multiple_flow.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <exception>
#include <mutex>
#include <thread>

#include "core/buffer.hpp"

namespace ft::erosion {
namespace {

// Quinn et al. (1991): the width of the contour a cell shares with a
// neighbour, in cells: half the side toward a cardinal neighbour, a quarter
// of the diagonal toward a diagonal one.
constexpr double kContour[2] = {0.5, M_SQRT2 / 4.0};

// The share of the time the first pass (each cell's givers, lower
// neighbours and shares) takes; the topological pass has the rest.
constexpr double kSetupShare = 0.3;
constexpr int32_t kSetupBands = 4;

// What one thread owns: a band of rows, the cells of it that are ready, and
// the cells of it that other threads made ready.
struct alignas(64) Band {
  int32_t y0 = 0, y1 = 0;
  std::vector<int32_t> ready;
  std::mutex inbox_lock;
  std::vector<int32_t> inbox;
  std::atomic<int64_t> done{0};
};

// What the first pass reads and writes (see multiple_flow_area).
struct Setup {
  const float* z;
  const uint8_t* sea;
  int64_t sink;
  const int64_t* offset;
  const double* factor;
  double cell;
  uint8_t *higher, *lower, *waiting;
  double *total, *area;
};

// The first pass on cells x0 .. x1 - 1 of row `row` (an index), each with
// eight neighbours that are inner cells at the fixed offsets: selects
// instead of branches on the heights (one of three compares mispredicted,
// and this pass was 60% of the area's time), the same sums in the same
// order as the general path (adding 0.0 to a sum of positive terms
// changes no bit).
[[gnu::noinline]] void setup_interior(const Setup& s, int64_t row, int32_t x0, int32_t x1) {
  const float* __restrict z = s.z;
  const int64_t o[8] = {s.offset[0], s.offset[1], s.offset[2], s.offset[3],
                        s.offset[4], s.offset[5], s.offset[6], s.offset[7]};
  const double f[8] = {s.factor[0], s.factor[1], s.factor[2], s.factor[3],
                       s.factor[4], s.factor[5], s.factor[6], s.factor[7]};
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    const bool giver = i != s.sink && !(s.sea && s.sea[i]);
    const float zi = z[i];
    unsigned up = 0, down = 0;
    double sum = 0.0;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const float zj = z[i + o[k]];
      const bool lower = giver & (zj < zi);
      // A sea cell gives nothing: a cell waiting for one waited forever.
      up |= unsigned((zj > zi) & !(s.sea && s.sea[i + o[k]])) << k;
      down |= unsigned(lower) << k;
      const double share = f[k] * (double(zi) - double(zj));
      sum += lower ? share : 0.0;
    }
    s.higher[i] = uint8_t(up);
    s.lower[i] = uint8_t(down);
    s.waiting[i] = uint8_t(std::popcount(up));
    s.total[i] = sum;
    s.area[i] = s.cell;
  }
}

}  // namespace

void multiple_flow_area(const D8Grid& g, const float* z, int32_t sink, std::vector<double>& area,
                        const Progress& progress, const FlatGrading* flats, const Inflow* inflow) {
  if (flats && flats->flat_cells == 0) flats = nullptr;  // (its arrays are empty then)
  const size_t n = g.size();
  const int32_t w = g.width, h = g.height;
  // Interior cells (all eight neighbours inside, also on a torus) take them
  // at fixed offsets; the others through the general lookup.
  int64_t offset[8];
  double factor[8];  // contour length over distance
  for (int k = 0; k < 8; ++k) {
    offset[k] = int64_t(kDy[k]) * w + kDx[k];
    factor[k] = kContour[k & 1] / g.distance(k);
  }
  auto inner = [&](int32_t x, int32_t y) { return x > 0 && y > 0 && x < w - 1 && y < h - 1; };
  auto nbr = [&](int64_t i, int32_t x, int32_t y, bool in, int k) { return in ? i + offset[k] : g.neighbour(x, y, k); };
  // A base level keeps what reaches it; every other cell gives.
  auto gives = [&](int64_t i, int32_t x, int32_t y) {
    return (g.periodic ? i != sink : inner(x, y)) && !g.in_sea(size_t(i));
  };

  // Per cell, in parallel rows (each writes only its own): its higher
  // givers and its lower neighbours as bit masks by direction (the loops
  // below then skip the others without a branch on heights), how many
  // higher givers it waits for, and, for a giver, the sum of its shares
  // (contour length x slope toward each lower neighbour).
  Buffer<uint8_t> waiting(n), higher(n), lower(n);
  Buffer<double> total(n);
  area.resize(n);
  const double cell = g.spacing * g.spacing;
  auto setup_cell = [&](int32_t x, int32_t y) {
    const int64_t i = int64_t(y) * w + x;
    const bool in = inner(x, y), giver = gives(i, x, y);
    unsigned up = 0, down = 0;
    double sum = 0.0;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = nbr(i, x, y, in, k);
      if (j < 0) continue;
      // (A torus's sink gives nothing, but it is the lowest cell: never
      // a higher one.)
      if (z[j] > z[i]) {
        up |= unsigned((g.periodic || inner(x + kDx[k], y + kDy[k])) && !g.in_sea(size_t(j))) << k;
      } else if (giver && z[j] < z[i]) {
        down |= 1u << k;
        sum += factor[k] * (double(z[i]) - double(z[j]));
      }
    }
    higher[size_t(i)] = uint8_t(up);
    lower[size_t(i)] = uint8_t(down);
    waiting[size_t(i)] = uint8_t(std::popcount(up));
    total[size_t(i)] = sum;
    area[size_t(i)] = cell;
  };
  // On a flat (the heights equal), a cell gives to its neighbours of the
  // same height whose key is lower (flat_resolution.hpp), in proportion to
  // contour length times the key's fall, and takes from those whose key is
  // higher: the masks and shares of the flats' cells and their outlets, made
  // again from the keys after the heights' pass over their row.
  const uint8_t* level = flats ? flats->level.data() : nullptr;
  const int32_t* key = flats ? flats->key.data() : nullptr;
  auto grade_row = [&](int32_t y) {
    const int64_t row = int64_t(y) * w;
    for (int32_t x = 0; x < w; ++x) {
      const int64_t i = row + x;
      if (!level[i]) continue;
      const bool in = inner(x, y);
      // (A key above 0: a flat cell. The comparisons are a coin toss on a
      // flat: without branches.)
      const int32_t ki = key[i];
      unsigned up = higher[size_t(i)], down = lower[size_t(i)];
      double sum = total[size_t(i)];
      for (unsigned m = level[i]; m; m &= m - 1) {
        const int k = std::countr_zero(m);
        const int64_t j = nbr(i, x, y, in, k);
        const int32_t kj = key[j];
        const bool gives = kj > ki && !g.in_sea(size_t(j)), takes = ki > 0 && kj < ki;
        up |= unsigned(gives) << k;
        down |= unsigned(takes) << k;
        sum += takes ? factor[k] * double(ki - kj) : 0.0;
      }
      higher[size_t(i)] = uint8_t(up);
      lower[size_t(i)] = uint8_t(down);
      waiting[size_t(i)] = uint8_t(std::popcount(up));
      total[size_t(i)] = sum;
    }
  };
  // What a giver j gives i per unit: contour length over distance times the
  // fall, of the heights or, on a flat, of the keys.
  auto fall = [&](int64_t j, int64_t i) {
    const double d = double(z[j]) - double(z[i]);
    return key && d == 0.0 ? double(key[j] - key[i]) : d;
  };
  // Cells whose neighbours are all inner cells (a torus: all cells off its
  // first and last rows and columns) go through the branch-free kernel.
  const int32_t margin = g.periodic ? 1 : 2;
  const Setup setup{z, g.sea, sink, offset, factor, cell, higher.data(), lower.data(), waiting.data(), total.data(),
                    area.data()};
  // In bands of rows, with a report after each (a 4097^2 grid's pass took
  // 0.7 s of CPU, 1.8 s at load 5).
  for (int32_t band = 0; band < kSetupBands; ++band) {
    const int32_t y0 = int32_t(int64_t(h) * band / kSetupBands), y1 = int32_t(int64_t(h) * (band + 1) / kSetupBands);
#pragma omp parallel for schedule(static)
    for (int32_t y = y0; y < y1; ++y) {
      if (y < margin || y >= h - margin || w <= 2 * margin) {
        for (int32_t x = 0; x < w; ++x) setup_cell(x, y);
        if (flats) grade_row(y);
        continue;
      }
      for (int32_t x = 0; x < margin; ++x) setup_cell(x, y);
      setup_interior(setup, int64_t(y) * w, margin, w - margin);
      for (int32_t x = w - margin; x < w; ++x) setup_cell(x, y);
      if (flats) grade_row(y);
    }
    progress.report(kSetupShare * (band + 1) / kSetupBands);
  }
  if (inflow)
    for (const auto& [i, a] : *inflow) area[size_t(i)] += a;

  // Kahn's order, pulled: a cell is ready when its last higher giver is
  // done; it then takes from each higher giver, in neighbour order, the
  // giver's area over its total shares times the share toward it. Each sum
  // is made in a fixed order from final values, so the areas do not depend
  // on which thread does a cell or when. Each thread owns a band of rows and keeps
  // its ready cells on a stack (the cell taken next is usually one just
  // made ready beside the last: still in the cache). Only cells in the
  // first and last row of a band have higher givers in another band: their
  // counts are atomic, and a cell another thread made ready goes to its
  // owner's inbox.
  const int most = std::max(1, std::min<int>(omp_get_max_threads(), h / 4));
  std::vector<Band> bands(static_cast<size_t>(most));
  int team = 1;  // the threads OpenMP gives (fewer inside another parallel region)
  auto owner = [&](int32_t y) {
    int b = int(int64_t(y) * team / h);
    while (y < bands[b].y0) --b;
    while (y >= bands[b].y1) ++b;
    return b;
  };
  std::vector<uint8_t> shared(size_t(h), 0);  // rows whose cells other bands make ready too
  // The calling thread (OpenMP's thread 0) reports the cells done by all
  // bands, every 64th of the grid (a 4097^2 grid takes seconds); a cancel
  // there stops every band at its next look at `stop` and is rethrown below.
  const int64_t every = std::max<int64_t>(int64_t(n) / 64, 4096);
  int64_t next_report = every;
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  auto report = [&](int64_t all) {
    if (all < next_report) return;
    next_report = all + every;
    try {
      progress.report(kSetupShare + (1.0 - kSetupShare) * double(all) / double(n));
    } catch (...) {
      error = std::current_exception();
      stop.store(true, std::memory_order_relaxed);
    }
  };
  auto all_done = [&] {
    int64_t all = 0;
    for (int b = 0; b < team; ++b) all += bands[b].done.load(std::memory_order_acquire);
    return all;
  };
#pragma omp parallel num_threads(most)
  {
#pragma omp single
    {
      team = omp_get_num_threads();
      for (int b = 0; b < team; ++b) {
        bands[b].y0 = int32_t(int64_t(h) * b / team);
        bands[b].y1 = int32_t(int64_t(h) * (b + 1) / team);
        if (team > 1) shared[size_t(bands[b].y0)] = shared[size_t(bands[b].y1 - 1)] = 1;
      }
    }  // (a barrier)
    const int id = omp_get_thread_num();
    Band& me = bands[id];
    me.ready.reserve(size_t(me.y1 - me.y0) * w / 4);
    for (int64_t i = int64_t(me.y1) * w; i-- > int64_t(me.y0) * w;)
      if (waiting[size_t(i)] == 0) me.ready.push_back(int32_t(i));
    // Every band lists its first ready cells before any count changes: a
    // cell another thread makes ready meanwhile would be listed twice.
#pragma omp barrier
    int64_t done = 0;
    for (;;) {
      while (!me.ready.empty()) {
        const int32_t i = me.ready.back();
        me.ready.pop_back();
        const int32_t x = i % w, y = i / w;
        const bool in = inner(x, y);
        double sum = area[size_t(i)];
        for (unsigned m = higher[size_t(i)]; m; m &= m - 1) {
          const int k = std::countr_zero(m);
          const int64_t j = nbr(i, x, y, in, k);
          sum += total[size_t(j)] * (factor[k] * fall(j, i));
        }
        area[size_t(i)] = sum;
        if ((++done & 4095) == 0) {
          me.done.store(done, std::memory_order_release);
          if (id == 0) report(all_done());
          if (stop.load(std::memory_order_relaxed)) break;
        }
        if (!gives(i, x, y)) continue;
        // What it gives per unit of share, in place of the total: its lower
        // neighbours read it only after the counts below.
        total[size_t(i)] = sum / total[size_t(i)];
        for (unsigned m = lower[size_t(i)]; m; m &= m - 1) {
          const int k = std::countr_zero(m);
          const int64_t j = nbr(i, x, y, in, k);
          const int32_t jy = g.periodic ? (y + kDy[k] + h) % h : y + kDy[k];
          if (!shared[size_t(jy)]) {
            if (--waiting[size_t(j)] == 0) me.ready.push_back(int32_t(j));
            continue;
          }
          if (std::atomic_ref<uint8_t>(waiting[size_t(j)]).fetch_sub(1, std::memory_order_acq_rel) != 1) continue;
          const int b = owner(jy);
          if (b == id) {
            me.ready.push_back(int32_t(j));
          } else {
            std::lock_guard<std::mutex> lock(bands[b].inbox_lock);
            bands[b].inbox.push_back(int32_t(j));
          }
        }
      }
      me.done.store(done, std::memory_order_release);
      if (stop.load(std::memory_order_relaxed)) break;
      {
        std::lock_guard<std::mutex> lock(me.inbox_lock);
        me.ready.swap(me.inbox);
      }
      if (!me.ready.empty()) continue;
      const int64_t all = all_done();
      if (all == int64_t(n)) break;
      if (id == 0) report(all);
      std::this_thread::yield();
    }
  }
  if (error) std::rethrow_exception(error);
  progress.report(1.0);
}

std::vector<std::array<double, 8>> multiple_flow_given(const D8Grid& g, const float* z, int32_t sink,
                                                       const FlatGrading* flats, const std::vector<double>& area) {
  if (flats && flats->flat_cells == 0) flats = nullptr;
  std::vector<std::array<double, 8>> given(g.size());
  double factor[8];
  for (int k = 0; k < 8; ++k) factor[k] = kContour[k & 1] / g.distance(k);
  for (int32_t y = 0; y < g.height; ++y)
    for (int32_t x = 0; x < g.width; ++x) {
      const size_t i = size_t(y) * g.width + x;
      given[i].fill(0.0);
      if (g.is_base(int32_t(i), x, y, sink)) continue;
      // The shares as multiple_flow_area's setup and grading make them.
      double share[8] = {}, total = 0.0;
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(x, y, k);
        if (j < 0) continue;
        if (z[j] < z[i]) share[k] = factor[k] * (double(z[i]) - double(z[j]));
        else if (flats && z[j] == z[i] && (flats->level[i] >> k & 1u) && flats->key[i] > 0 &&
                 flats->key[j] < flats->key[i])
          share[k] = factor[k] * double(flats->key[i] - flats->key[j]);
        total += share[k];
      }
      if (total > 0)
        for (int k = 0; k < 8; ++k) given[i][k] = area[i] / total * share[k];
    }
  return given;
}

}  // namespace ft::erosion
