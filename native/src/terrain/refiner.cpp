// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/refiner.hpp"

#include <cmath>

#include "core/parallel.hpp"
#include "terrain/midpoint_steps.hpp"

namespace ft::terrain {
namespace detail {

Refiner::Refiner(const DiamondSquareConfig& c, Heightfield& hf)
    : c_(c), n_(1 << c.levels), w_(n_ + 1), x_(hf.data()), threads_(resolve_threads(c.threads)) {
  ref_step_ = c.reference ? n_ >> c.ref_levels : 0;
}

void Refiner::run() {
  first_touch();
  int first_stage = 1;
  if (c_.reference) {
    place_reference();
    first_stage = c_.ref_levels + 1;
  } else {
    place_corners();
  }
  // Progress: samples visited over samples to visit (the bands' sizes).
  for (int s = first_stage; s <= c_.levels; ++s) total_ += stage_samples(s);
  // delta before stage s's square step is sigma 2^(-(2s - 1) H / 2); the
  // stages a reference grid stands for are skipped, not re-run.
  double delta = c_.sigma * std::pow(0.5, 0.5 * c_.hurst * 2.0 * (first_stage - 1));
  const double shrink = std::pow(0.5, 0.5 * c_.hurst);
  for (int s = first_stage; s <= c_.levels; ++s) {
    const int big = n_ >> (s - 1), half = big / 2;
    const double square_delta = delta * shrink;
    delta = square_delta * shrink;
    if (c_.additions) additions_stage(s, big, half, float(square_delta), float(delta));
    else fused_stage(s, big, half, float(square_delta), float(delta));
  }
  c_.progress.report(1.0);
}

// The grid is fresh memory: the kernel zeroes each page on its first touch,
// a quarter of the single-threaded run at 8193^2. The coarse stages touch
// every page (a row every few MB) on one thread, so that zeroing was serial;
// touching the pages here spreads it over the team. Values are written by
// the stages as before.
void Refiner::first_touch() {
  const size_t n = size_t(w_) * size_t(w_), page = 4096 / sizeof(float);
  const int team = threads_for(n);
  if (team < 2) return;
  const int64_t pages = int64_t((n + page - 1) / page);
#pragma omp parallel for num_threads(team) schedule(static)
  for (int64_t i = 0; i < pages; ++i) x_[size_t(i) * page] = 0.0f;
}

void Refiner::place_corners() {
  float g[4];
  gaussian_fill(c_.seed, Counter{0, 0, Stream::kTerrainCorners}, 0, 4, g);
  const float s = float(c_.sigma);
  if (c_.periodic) {
    at(0, 0) = at(n_, 0) = at(0, n_) = at(n_, n_) = s * g[0];
  } else {
    at(0, 0) = s * g[0];
    at(n_, 0) = s * g[1];
    at(0, n_) = s * g[2];
    at(n_, n_) = s * g[3];
  }
}

void Refiner::place_reference() {
  const int m = (1 << c_.ref_levels) + 1;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) at(i * ref_step_, j * ref_step_) = c_.reference[size_t(j) * m + i];
}

// Samples the bands of stage s visit, in the same (rows x per_row) units.
double Refiner::stage_samples(int s) const {
  const int big = n_ >> (s - 1), half = big / 2, cells = n_ / big;
  double sum = double(cells) * cells + double(2 * cells + 1) * (cells + 1);
  if (c_.additions) {
    const double a = addition_count(0, big), b = addition_count(half, big);
    sum += 2 * a * a + b * b;
  }
  return sum;
}

int Refiner::addition_count(int origin, int step) const {
  const int limit = c_.periodic ? n_ - 1 : n_;
  return origin > limit ? 0 : (limit - origin) / step + 1;
}

// The centres of square row j (at y = half + j big), draws keyed by the
// row's place in stage s's own grid (see stage_row).
void Refiner::square_one_row(int s, int j, int big, int half, float delta, float* g) {
  const int cells = n_ / big, y = half + j * big;
  gaussian_fill(c_.seed, Counter{stage_row(y, half), uint32_t(s), Stream::kTerrainSquare}, 0, cells, g);
  square_row(row(y), row(y - half), row(y + half), half, cells, big, half, delta, g);
}

// The diamond points of row y, draws keyed by the row's place in stage s's
// grid: on a grid row (y a multiple of big) the points at odd multiples of
// half, else every multiple of big.
void Refiner::diamond_one_row(int s, int y, int big, int half, float delta, float* g) {
  const int cells = n_ / big;
  const bool on_grid_row = (y / half) % 2 == 0;
  const int x0 = on_grid_row ? half : 0;
  const int count = on_grid_row ? cells : cells + 1;
  gaussian_fill(c_.seed, Counter{stage_row(y, half), uint32_t(s), Stream::kTerrainDiamond}, 0, count, g);
  diamond_row(y, x0, count, big, half, delta, g);
}

void Refiner::diamond_row(int y, int x0, int count, int big, int half, float delta, const float* g) {
  float* r = row(y);
  const bool interior_row = y - half >= 0 && y + half <= n_;
  // Interior points of an interior row: 4 neighbours, the hot loop.
  if (interior_row) {
    const int lo = x0 == 0 ? 1 : 0;
    const int hi = (x0 + (count - 1) * big == n_) ? count - 1 : count;
    diamond_interior(r, row(y - half), row(y + half), x0 + lo * big, hi - lo, big, half, delta, g + lo);
    if (lo == 1) r[x0] = edge_point(x0, y, half) + delta * g[0];
    if (hi == count - 1) {
      const int x = x0 + (count - 1) * big;
      if (!(c_.periodic && x == n_)) r[x] = edge_point(x, y, half) + delta * g[count - 1];
    }
    return;
  }
  for (int i = 0; i < count; ++i) {
    const int x = x0 + i * big;
    if (c_.periodic && x == n_) continue;
    r[x] = edge_point(x, y, half) + delta * g[i];
  }
}

// Mean of the neighbours of a border point: the 3 that exist, or all 4
// with wrap-around when periodic.
float Refiner::edge_point(int x, int y, int half) {
  if (c_.periodic) {
    auto wrap = [this](int v) { return v < 0 ? v + n_ : (v >= n_ ? v - n_ : v); };
    return interior_mean(at(wrap(x - half), y), at(wrap(x + half), y), at(x, wrap(y - half)), at(x, wrap(y + half)));
  }
  return border_mean(x - half >= 0 ? &at(x - half, y) : nullptr, x + half <= n_ ? &at(x + half, y) : nullptr,
                     y - half >= 0 ? &at(x, y - half) : nullptr, y + half <= n_ ? &at(x, y + half) : nullptr);
}

void Refiner::wrap_edges() {
  for (int x = 0; x < n_; ++x) at(x, n_) = at(x, 0);
  for (int y = 0; y <= n_; ++y) at(n_, y) = at(0, y);
}

}  // namespace detail

Heightfield diamond_square(const DiamondSquareConfig& config) {
  const int side = (1 << config.levels) + 1;
  Heightfield hf(side, side);
  detail::Refiner(config, hf).run();
  return hf;
}

}  // namespace ft::terrain
