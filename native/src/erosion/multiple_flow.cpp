// Multiple-flow drainage area (see multiple_flow.hpp).
#include "erosion/multiple_flow.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <mutex>
#include <thread>

#include "core/buffer.hpp"

namespace ft::erosion {
namespace {

// Quinn et al. (1991): the width of the contour a cell shares with a
// neighbour, in cells: half the side toward a cardinal neighbour, a quarter
// of the diagonal toward a diagonal one.
constexpr double kContour[2] = {0.5, M_SQRT2 / 4.0};

// What one thread owns: a band of rows, the cells of it that are ready, and
// the cells of it that other threads made ready.
struct alignas(64) Band {
  int32_t y0 = 0, y1 = 0;
  std::vector<int32_t> ready;
  std::mutex inbox_lock;
  std::vector<int32_t> inbox;
  std::atomic<int64_t> done{0};
};

}  // namespace

void multiple_flow_area(const D8Grid& g, const float* z, int32_t sink, std::vector<double>& area) {
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
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
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
          up |= unsigned(g.periodic || inner(x + kDx[k], y + kDy[k])) << k;
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
    }

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
          sum += total[size_t(j)] * (factor[k] * (double(z[j]) - double(z[i])));
        }
        area[size_t(i)] = sum;
        ++done;
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
      {
        std::lock_guard<std::mutex> lock(me.inbox_lock);
        me.ready.swap(me.inbox);
      }
      if (!me.ready.empty()) continue;
      int64_t all = 0;
      for (int b = 0; b < team; ++b) all += bands[b].done.load(std::memory_order_acquire);
      if (all == int64_t(n)) break;
      std::this_thread::yield();
    }
  }
}

}  // namespace ft::erosion
