#include "terrain/diamond_square.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <omp.h>

#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace ft {
namespace {

// Each step runs over its rows in bands of about this many samples, with a
// progress report between bands: a level-14 terrain's last stage is ~2.7e8
// samples (seconds of work), a band a few milliseconds, so a cancel lands
// within a fraction of a second. Bands only split a row loop, and no row
// reads what another row of the same step writes, so the output is the same.
constexpr int64_t kBandSamples = int64_t(1) << 20;

// The hot loops. The last stage (stride 2) holds three quarters of all
// points; with the stride known at compile time its loops vectorise (even/odd
// lane shuffles). Compiled for AVX2 and baseline x86-64: the arithmetic of a
// point is the same on every path (no FMA contraction), so are the bits.
template <int kStride>
inline void square_points(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                          float delta, const float* g) {
  const int stride = kStride ? kStride : big, h = kStride ? kStride / 2 : half;
  for (int i = 0; i < count; ++i) {
    const int x = x0 + i * stride;
    row[x] = 0.25f * ((up[x - h] + up[x + h]) + (dn[x - h] + dn[x + h])) + delta * g[i];
  }
}

template <int kStride>
inline void diamond_points(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                           float delta, const float* g) {
  const int stride = kStride ? kStride : big, h = kStride ? kStride / 2 : half;
  for (int i = 0; i < count; ++i) {
    const int x = x0 + i * stride;
    row[x] = 0.25f * ((row[x - h] + row[x + h]) + (up[x] + dn[x])) + delta * g[i];
  }
}

__attribute__((target_clones("avx2", "default")))
void square_row(float* row, const float* up, const float* dn, int x0, int count, int big, int half, float delta,
                const float* g) {
  if (big == 2) square_points<2>(row, up, dn, x0, count, big, half, delta, g);
  else square_points<0>(row, up, dn, x0, count, big, half, delta, g);
}

__attribute__((target_clones("avx2", "default")))
void diamond_interior(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                      float delta, const float* g) {
  if (big == 2) diamond_points<2>(row, up, dn, x0, count, big, half, delta, g);
  else diamond_points<0>(row, up, dn, x0, count, big, half, delta, g);
}

// One grid being refined; the stage methods are the steps of MidPointFM2D.
class Refiner {
 public:
  Refiner(const DiamondSquareConfig& c, Heightfield& hf)
      : c_(c), n_(1 << c.levels), w_(n_ + 1), x_(hf.data()), threads_(resolve_threads(c.threads)) {
    ref_step_ = c.reference ? n_ >> c.ref_levels : 0;
  }

  void run() {
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
      if (!c_.additions) {
        fused_stage(s, big, half, float(square_delta), float(delta));
        continue;
      }
      square_step(s, big, half, float(square_delta));
      add_to_grid(s, 0, big, float(square_delta), Stream::kTerrainAddOld);
      diamond_step(s, big, half, float(delta));
      {
        add_to_grid(s, 0, big, float(delta), Stream::kTerrainAddNew);
        add_to_grid(s, half, big, float(delta), Stream::kTerrainAddHalf);
      }
    }
    c_.progress.report(1.0);
  }

 private:
  float& at(int x, int y) { return x_[size_t(y) * w_ + x]; }

  void place_corners() {
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

  void place_reference() {
    const int m = (1 << c_.ref_levels) + 1;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) at(i * ref_step_, j * ref_step_) = c_.reference[size_t(j) * m + i];
  }

  // Samples the bands of stage s visit, in the same (rows x per_row) units.
  double stage_samples(int s) const {
    const int big = n_ >> (s - 1), half = big / 2, cells = n_ / big;
    double sum = double(cells) * cells + double(2 * cells + 1) * (cells + 1);
    if (c_.additions) {
      const double a = addition_count(0, big), b = addition_count(half, big);
      sum += 2 * a * a + b * b;
    }
    return sum;
  }

  int addition_count(int origin, int step) const {
    const int limit = c_.periodic ? n_ - 1 : n_;
    return origin > limit ? 0 : (limit - origin) / step + 1;
  }

  // Calls rows_fn(r0, r1) for consecutive row ranges covering 0..rows-1,
  // each about kBandSamples samples, reporting progress after each.
  template <class RowsFn>
  void in_bands(int rows, int per_row, RowsFn&& rows_fn) {
    const int band = int(std::max<int64_t>(1, kBandSamples / std::max(1, per_row)));
    for (int r0 = 0; r0 < rows; r0 += band) {
      const int r1 = std::min(rows, r0 + band);
      rows_fn(r0, r1);
      done_ += double(r1 - r0) * double(per_row);
      c_.progress.report(std::min(1.0, done_ / total_));
    }
  }

  bool pinned(int x, int y) const {
    return ref_step_ != 0 && x % ref_step_ == 0 && y % ref_step_ == 0;
  }

  // A stage of plain midpoint displacement with its square and diamond steps
  // fused row by row: square row j, then the diamond points of that centre
  // row, then those of the grid row above it, whose square rows are both
  // done. A few rows stay in cache instead of two sweeps over the whole grid
  // (at 8193^2 the grid is 268 MB). Every point reads exactly the values it
  // reads in the two-sweep order (diamond points never read each other), so
  // the output is bit-identical. Additions change old points between the
  // steps, so they keep the two sweeps.
  void fused_stage(int s, int big, int half, float square_delta, float diamond_delta) {
    const int cells = n_ / big;
    in_bands(cells, 3 * cells + 1, [&](int j0, int j1) {
      const int team = threads_for(size_t(j1 - j0) * size_t(cells) * 3);
#pragma omp parallel num_threads(team)
      {
        std::vector<float> g(size_t(cells) + 5);
        const int parts = omp_get_num_threads(), id = omp_get_thread_num();
        const int b0 = j0 + (j1 - j0) * id / parts, b1 = j0 + (j1 - j0) * (id + 1) / parts;
        for (int j = b0; j < b1; ++j) {
          square_one_row(s, j, big, half, square_delta, g.data());
          diamond_one_row(s, half + j * big, big, half, diamond_delta, g.data());
          if (j > b0) diamond_one_row(s, j * big, big, half, diamond_delta, g.data());
        }
        // The grid row at the start of each part needs the square row of the
        // part before it.
#pragma omp barrier
        if (b0 < b1 && !(b0 == 0 && c_.periodic)) diamond_one_row(s, b0 * big, big, half, diamond_delta, g.data());
      }
    });
    std::vector<float> g(size_t(cells) + 5);
    if (c_.periodic) {
      diamond_one_row(s, 0, big, half, diamond_delta, g.data());  // wraps to the last square row
      wrap_edges();
    } else {
      diamond_one_row(s, n_, big, half, diamond_delta, g.data());
    }
  }

  void square_one_row(int s, int j, int big, int half, float delta, float* g) {
    const int cells = n_ / big, y = half + j * big;
    gaussian_fill(c_.seed, Counter{uint32_t(y), uint32_t(s), Stream::kTerrainSquare}, 0, cells, g);
    square_row(x_ + size_t(y) * w_, x_ + size_t(y - half) * w_, x_ + size_t(y + half) * w_, half, cells, big, half,
               delta, g);
  }

  // The diamond points of row y (its draws keyed by row, as in diamond_step).
  void diamond_one_row(int s, int y, int big, int half, float delta, float* g) {
    const int cells = n_ / big;
    const bool on_grid_row = (y / half) % 2 == 0;
    const int x0 = on_grid_row ? half : 0;
    const int count = on_grid_row ? cells : cells + 1;
    gaussian_fill(c_.seed, Counter{uint32_t(y), uint32_t(s), Stream::kTerrainDiamond}, 0, count, g);
    diamond_row(y, x0, count, big, half, delta, g);
  }

  // Square step: centres of the squares of side `big`.
  void square_step(int s, int big, int half, float delta) {
    const int cells = n_ / big;
    in_bands(cells, cells, [&](int j0, int j1) {
#pragma omp parallel num_threads(threads_for(size_t(j1 - j0) * size_t(cells)))
      {
        std::vector<float> g(size_t(cells) + 4);
#pragma omp for schedule(static)
        for (int j = j0; j < j1; ++j) {
          const int y = half + j * big;
          gaussian_fill(c_.seed, Counter{uint32_t(y), uint32_t(s), Stream::kTerrainSquare}, 0, cells, g.data());
          const float* up = x_ + size_t(y - half) * w_;
          const float* dn = x_ + size_t(y + half) * w_;
          float* row = x_ + size_t(y) * w_;
          square_row(row, up, dn, half, cells, big, half, delta, g.data());
        }
      }
    });
  }

  // Diamond step: the edge midpoints, from their 4 axis neighbours (3 on a
  // border, or wrapped around when periodic).
  void diamond_step(int s, int big, int half, float delta) {
    const int cells = n_ / big;
    const int rows = 2 * cells + 1;
    in_bands(rows, cells + 1, [&](int r0, int r1) {
#pragma omp parallel num_threads(threads_for(size_t(r1 - r0) * size_t(cells)))
      {
        std::vector<float> g(size_t(cells) + 5);
#pragma omp for schedule(static)
        for (int r = r0; r < r1; ++r) {
          const int y = r * half;
          if (c_.periodic && y == n_) continue;  // copied from row 0 below
          const bool on_grid_row = (r % 2) == 0;  // y is a multiple of `big`
          const int x0 = on_grid_row ? half : 0;
          const int count = on_grid_row ? cells : cells + 1;
          gaussian_fill(c_.seed, Counter{uint32_t(y), uint32_t(s), Stream::kTerrainDiamond}, 0, count, g.data());
          diamond_row(y, x0, count, big, half, delta, g.data());
        }
      }
    });
    if (c_.periodic) wrap_edges();
  }

  void diamond_row(int y, int x0, int count, int big, int half, float delta, const float* g) {
    float* row = x_ + size_t(y) * w_;
    const bool interior_row = y - half >= 0 && y + half <= n_;
    const float* up = interior_row ? x_ + size_t(y - half) * w_ : nullptr;
    const float* dn = interior_row ? x_ + size_t(y + half) * w_ : nullptr;
    int i = 0;
    // Interior points of an interior row: 4 neighbours, the hot loop.
    if (interior_row) {
      const int lo = x0 == 0 ? 1 : 0;
      const int hi = (x0 + (count - 1) * big == n_) ? count - 1 : count;
      diamond_interior(row, up, dn, x0 + lo * big, hi - lo, big, half, delta, g + lo);
      if (lo == 1) row[x0] = edge_point(x0, y, half) + delta * g[0];
      if (hi == count - 1) {
        const int x = x0 + (count - 1) * big;
        if (!(c_.periodic && x == n_)) row[x] = edge_point(x, y, half) + delta * g[count - 1];
      }
      return;
    }
    for (i = 0; i < count; ++i) {
      const int x = x0 + i * big;
      if (c_.periodic && x == n_) continue;
      row[x] = edge_point(x, y, half) + delta * g[i];
    }
  }

  // Mean of the neighbours of a border point: the 3 that exist, or all 4
  // with wrap-around when periodic.
  float edge_point(int x, int y, int half) {
    if (c_.periodic) {
      auto wrap = [this](int v) { return v < 0 ? v + n_ : (v >= n_ ? v - n_ : v); };
      return 0.25f * ((at(wrap(x - half), y) + at(wrap(x + half), y)) +
                      (at(x, wrap(y - half)) + at(x, wrap(y + half))));
    }
    float sum = 0.0f;
    int k = 0;
    if (x - half >= 0) sum += at(x - half, y), ++k;
    if (x + half <= n_) sum += at(x + half, y), ++k;
    if (y - half >= 0) sum += at(x, y - half), ++k;
    if (y + half <= n_) sum += at(x, y + half), ++k;
    return sum / float(k);
  }

  // Feder's additions: every point of the grid with spacing `step` starting
  // at `origin` gets delta g (reference nodes stay as given).
  void add_to_grid(int level, int origin, int step, float delta, Stream stream) {
    const int count = addition_count(origin, step);
    in_bands(count, count, [&](int j0, int j1) {
#pragma omp parallel num_threads(threads_for(size_t(j1 - j0) * size_t(count)))
      {
        std::vector<float> g(size_t(count) + 4);
#pragma omp for schedule(static)
        for (int j = j0; j < j1; ++j) {
          const int y = origin + j * step;
          gaussian_fill(c_.seed, Counter{uint32_t(y), uint32_t(level), stream}, 0, count, g.data());
          float* row = x_ + size_t(y) * w_;
          for (int i = 0; i < count; ++i) {
            const int x = origin + i * step;
            if (!pinned(x, y)) row[x] += delta * g[i];
          }
        }
      }
    });
    if (c_.periodic) wrap_edges();
  }

  void wrap_edges() {
    for (int x = 0; x < n_; ++x) at(x, n_) = at(x, 0);
    for (int y = 0; y <= n_; ++y) at(n_, y) = at(0, y);
  }

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

}  // namespace

Heightfield diamond_square(const DiamondSquareConfig& config) {
  const int side = (1 << config.levels) + 1;
  Heightfield hf(side, side);
  Refiner(config, hf).run();
  return hf;
}

}  // namespace ft
