// SPDX-License-Identifier: GPL-3.0-or-later
// Flats graded by random passage times (see flat_resolution.hpp).
#include "erosion/flat_resolution.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "erosion/flow_graph.hpp"

namespace ft::erosion {
namespace {

// A cell's cost factor is an integer uniform in kLeast .. 4.75 kLeast, so a
// path may wander some cells aside to save cost (on the test lake and the
// eroded default mountain, 0.2-1.5% of the flats' cells lay on straight
// runs of 16 or more; 2-3% with factors 4 .. 15, 31-35% with 4 .. 7). A
// cardinal step costs the two cells' factors added, a diagonal one that
// times sqrt 2 (as 181 / 128, 0.0002 short): integers, so the key's fall
// along a way out is exact.
constexpr int kFactorBits = 4;
constexpr int32_t kLeast = 4, kMostStep = 2 * (kLeast + (1 << kFactorBits) - 1) * 181 / 128;

// The search's word per cell: the distance found so far above the cell's
// factor less kLeast, so that one load brings both (the search waits on
// memory: its front runs across the grid).
constexpr int32_t kFar = INT32_MAX >> kFactorBits;  // not reached (yet)
inline int32_t distance_of(int32_t word) { return word >> kFactorBits; }
inline int32_t factor_of(int32_t word) { return kLeast + (word & ((1 << kFactorBits) - 1)); }

// The bar, by the parts' times (a 4097^2 default mountain eroded by Land:
// 0.2 s to find the flats, 0.05 s to draw the factors, 0.3 s to search).
constexpr double kFoundShare = 0.35, kDrawnShare = 0.45;

// Neighbour k of cell i at (x, y), or -1 outside a bounded grid: at fixed
// offsets off the edges.
struct Neighbours {
  const D8Grid& g;
  int64_t offset[8];
  explicit Neighbours(const D8Grid& grid) : g(grid) {
    for (int k = 0; k < 8; ++k) offset[k] = int64_t(kDy[k]) * g.width + kDx[k];
  }
  bool inner(int32_t x, int32_t y) const { return x > 0 && y > 0 && x < g.width - 1 && y < g.height - 1; }
  int64_t at(int64_t i, int32_t x, int32_t y, bool in, int k) const { return in ? i + offset[k] : g.neighbour(x, y, k); }
};

// Shortest paths from `sources` (distance 0) along the level masks, into
// `word` (kFar everywhere but the factors at first). Dial's bucket queue
// (the costs are small integers): cells leave in order of distance,
// serially; the distances depend neither on the thread count nor on the
// order of equal distances. `progress` hears the share of `cells` settled.
void passage_times(const D8Grid& g, const FlatGrading& flats, const std::vector<int32_t>& sources,
                   Buffer<int32_t>& word, int64_t cells, const Progress& progress) {
  const Neighbours nbr(g);
  std::array<std::vector<int32_t>, kMostStep + 1> bucket;
  for (const int32_t s : sources) {
    word[size_t(s)] &= (1 << kFactorBits) - 1;
    bucket[0].push_back(s);
  }
  const int64_t every = std::max<int64_t>(int64_t(g.size()) / 64, 4096);
  int64_t settled = 0, next_report = every, queued = int64_t(sources.size());
  for (int32_t d = 0; queued > 0; ++d) {
    std::vector<int32_t>& now = bucket[size_t(d % (kMostStep + 1))];
    // (A cell reached from distance d goes to a later bucket, never to this
    // one: every step costs 2 kLeast .. kMostStep.)
    for (const int32_t c : now) {
      const int32_t wc = word[size_t(c)];
      if (distance_of(wc) != d) continue;  // reached sooner since
      if (++settled == next_report) {
        progress.report(std::min(1.0, double(settled) / double(cells)));
        next_report += every;
      }
      const int32_t cx = c % g.width, cy = c / g.width;
      const bool in = nbr.inner(cx, cy);
      const int32_t fc = factor_of(wc);
      for (unsigned m = flats.level[size_t(c)]; m; m &= m - 1) {
        const int k = std::countr_zero(m);
        const int64_t j = nbr.at(c, cx, cy, in, k);
        const int32_t wj = word[size_t(j)], sum = fc + factor_of(wj);
        const int32_t to = d + ((k & 1) ? sum * 181 / 128 : sum);
        if (to < distance_of(wj)) {
          word[size_t(j)] = (to << kFactorBits) | (wj & ((1 << kFactorBits) - 1));
          bucket[size_t(to % (kMostStep + 1))].push_back(int32_t(j));
          ++queued;
        }
      }
    }
    queued -= int64_t(now.size());
    now.clear();
  }
}

}  // namespace

void resolve_flats(const D8Grid& g, const float* z, int32_t sink, FlatGrading& flats, const Progress& progress,
                   const FlatFrame* frame) {
  const size_t n = g.size();
  const Neighbours nbr(g);
  Buffer<uint8_t> flat(n);  // 1 on a flat
  flats.level = Buffer<uint8_t>(n);
  flats.key = Buffer<int32_t>();
  flats.flat_cells = 0;
  // 1. The flat cells, and each cell's neighbours of the same height; then
  //    a cell off the flats keeps only its flat ones. Rows in parallel, each
  //    writes its own cells. Inside (kInner) the neighbours lie at fixed
  //    offsets and the sea and a torus's sink are the only base levels: a
  //    third of the time of the bounds-checked path.
  auto classify = [&]<bool kInner>(int64_t i, int32_t x, int32_t y) {
    const float zi = z[i];
    unsigned lower = 0, level = 0;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const int64_t j = kInner ? i + nbr.offset[k] : g.neighbour(x, y, k);
      if (!kInner && j < 0) continue;
      lower |= z[j] < zi;
      level |= unsigned(z[j] == zi) << k;
    }
    const bool base = kInner ? g.in_sea(size_t(i)) || (g.periodic && i == sink) : g.is_base(int32_t(i), x, y, sink);
    const bool on_flat = !lower && !base;
    flat[size_t(i)] = on_flat;
    flats.level[size_t(i)] = uint8_t(level);
    return int64_t(on_flat);
  };
  int64_t flat_cells = 0;
#pragma omp parallel for schedule(static) reduction(+ : flat_cells)
  for (int32_t y = 0; y < g.height; ++y) {
    const int64_t row = int64_t(y) * g.width;
    if (y == 0 || y == g.height - 1 || g.width < 3) {
      for (int32_t x = 0; x < g.width; ++x) flat_cells += classify.template operator()<false>(row + x, x, y);
      continue;
    }
    flat_cells += classify.template operator()<false>(row, 0, y) +
                  classify.template operator()<false>(row + g.width - 1, g.width - 1, y);
    for (int32_t x = 1; x < g.width - 1; ++x) flat_cells += classify.template operator()<true>(row + x, x, y);
  }
  flats.flat_cells = flat_cells;
  if (flat_cells == 0) {
    flats.level = Buffer<uint8_t>();
    return;
  }
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < g.height; ++y)
    for (int32_t x = 0; x < g.width; ++x) {
      const int64_t i = int64_t(y) * g.width + x;
      unsigned level = flats.level[size_t(i)];
      if (!level || flat[size_t(i)]) continue;
      const bool in = nbr.inner(x, y);
      for (unsigned m = level; m; m &= m - 1) {
        const int k = std::countr_zero(m);
        if (!flat[size_t(nbr.at(i, x, y, in, k))]) level &= ~(1u << k);
      }
      flats.level[size_t(i)] = uint8_t(level);
    }
  // The outlets, in index order.
  std::vector<int32_t> outlets;
  for (int32_t i = 0; i < int32_t(n); ++i)
    if (!flat[size_t(i)] && flats.level[size_t(i)]) outlets.push_back(i);
  progress.report(kFoundShare);
  // 2. The cells' cost factors, in the search's words.
  flats.key = Buffer<int32_t>(n);
#pragma omp parallel
  {
    std::vector<float> u(size_t(g.width));
#pragma omp for schedule(static)
    for (int32_t y = 0; y < g.height; ++y) {
      if (frame)
        draw_uniforms_at(frame->whole, 0, 0, 0, Stream::kFlatRouting, frame->y0 + y, frame->x0, g.width, u.data());
      else
        draw_row_uniforms(g, g.periodic ? sink : -1, 0, Stream::kFlatRouting, y, u.data());
      int32_t* word = flats.key.data() + int64_t(y) * g.width;
      for (int32_t x = 0; x < g.width; ++x)
        word[x] = (kFar << kFactorBits) | int32_t(u[size_t(x)] * float(1 << kFactorBits));
    }
  }
  progress.report(kDrawnShare);
  // 3. The passage times from the outlets, over the flats.
  {
    const ProgressPart part(progress, kDrawnShare, 1.0 - kDrawnShare);
    passage_times(g, flats, outlets, flats.key, flat_cells + int64_t(outlets.size()), part.progress());
  }
  int64_t stranded = 0;
#pragma omp parallel for schedule(static) reduction(+ : stranded)
  for (int64_t i = 0; i < int64_t(n); ++i) {
    int32_t& key = flats.key[size_t(i)];
    key = distance_of(key);
    if (key == kFar) {
      stranded += flat[size_t(i)];
      key = 0;
    }
  }
  if (stranded > 0)
    fail(FT_ERR_INTERNAL, "resolve_flats: " + std::to_string(stranded) +
                              " cells of flats reach no outlet (the heights must be filled first)");
  progress.report(1.0);
}

}  // namespace ft::erosion
