// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <omp.h>

#include "core/buffer.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "terrain/midpoint_steps.hpp"

namespace ft::terrain {
namespace {

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

// Points spaced `step` over the inclusive global rectangle [x0, x1] x [y0, y1].
struct Region {
  int64_t x0, x1, y0, y1, step;
  int nx() const { return int((x1 - x0) / step + 1); }
  int ny() const { return int((y1 - y0) / step + 1); }
};

// A compact array of one stage's points over a region, or a view into a
// finer stage's array (row stride in floats, origin offset).
struct Grid {
  Region r;
  float* p = nullptr;
  size_t stride = 0;
  float* row(int j) const { return p + size_t(j) * stride; }
};

class WindowRefiner {
 public:
  WindowRefiner(const DiamondSquareConfig& c, int target_stage)
      : c_(c), n_(int64_t(1) << c.levels), target_(target_stage), threads_(resolve_threads(c.threads)) {
    first_ = c.reference ? c.ref_levels + 1 : 1;
    ref_step_ = c.reference ? n_ >> c.ref_levels : 0;
  }

  // Fills out (window.width x window.height) with the points of the target
  // stage at (x0 + i, y0 + j) in units of that stage's spacing.
  void run(const Window& w, float* out) {
    const int64_t unit = n_ >> target_;
    Region target{w.x0 * unit, (w.x0 + w.width - 1) * unit, w.y0 * unit, (w.y0 + w.height - 1) * unit, unit};
    // The stages the target stands on: an initial grid (corners or the
    // reference) and the ones refined from it.
    const int start = std::min(first_ - 1, target_);
    std::vector<Region> need(size_t(target_ + 1));
    need[size_t(target_)] = target;
    for (int s = target_; s > start; --s) need[size_t(s - 1)] = grown(need[size_t(s)], n_ >> (s - 1));
    double total = 0, done = 0;
    for (int s = start + 1; s <= target_; ++s) total += double(need[size_t(s - 1)].nx()) * need[size_t(s - 1)].ny();

    Buffer<float> coarse = initial(need[size_t(start)]);
    Grid g{need[size_t(start)], coarse.data(), size_t(need[size_t(start)].nx())};
    double delta = c_.sigma * std::pow(0.5, 0.5 * c_.hurst * 2.0 * (first_ - 1));
    const double shrink = std::pow(0.5, 0.5 * c_.hurst);
    if (start == target_) {  // nothing to refine: the window lies on the initial grid
      for (int j = 0; j < w.height; ++j) std::copy_n(g.row(j), w.width, out + size_t(j) * size_t(w.width));
      return;
    }
    if (!c_.additions) {
      // Plain midpoint: each stage computes just its needed region, into one
      // of two arrays allocated once (stages alternate between them), and the
      // last stage straight into `out`: no per-stage allocation (whose first
      // touch cost a fifth of the run) and no final copy.
      Buffer<float> ping(stage_area(need, start + 1, target_ - 1)), pong(stage_area(need, start + 2, target_ - 1));
      for (int s = start + 1; s <= target_; ++s) {
        const double square_delta = delta * shrink;
        delta = square_delta * shrink;
        const Region& r = need[size_t(s)];
        Grid f{r, s == target_ ? out : ((s - start) % 2 ? ping.data() : pong.data()),
               s == target_ ? size_t(w.width) : size_t(r.nx())};
        midpoint_stage(g, s, f, float(square_delta), float(delta));
        g = f;
        done += double(r.nx()) * r.ny();
        c_.progress.report(std::min(1.0, done / total));
      }
      return;
    }
    Buffer<float> fine;
    for (int s = start + 1; s <= target_; ++s) {
      const double square_delta = delta * shrink;
      delta = square_delta * shrink;
      fine = refine(g, s, float(square_delta), float(delta));
      g = view(Grid{Region{g.r.x0, g.r.x1, g.r.y0, g.r.y1, g.r.step / 2}, fine.data(), size_t(2 * g.r.nx() - 1)},
               need[size_t(s)]);
      coarse = std::move(fine);
      done += double(g.r.nx()) * g.r.ny();
      c_.progress.report(std::min(1.0, done / total));
    }
    for (int j = 0; j < w.height; ++j) std::copy_n(g.row(j), w.width, out + size_t(j) * size_t(w.width));
  }

 private:
  int64_t canon(int64_t v) const {
    if (!c_.periodic) return v;
    const int64_t r = v % n_;
    return r < 0 ? r + n_ : r;
  }

  // The region of stage s - 1 (spacing big) that stage s needs to fill
  // `r`: every point of r reads points at most one coarse cell away (a
  // diamond point its square centres, which read their corners), so r grown
  // by two cells of the coarse grid, aligned to it, is enough.
  Region grown(const Region& r, int64_t big) const {
    Region g{floor_div(r.x0, big) * big - big, ceil_div(r.x1, big) * big + big,
             floor_div(r.y0, big) * big - big, ceil_div(r.y1, big) * big + big, big};
    if (!c_.periodic) {
      g.x0 = std::max<int64_t>(0, g.x0), g.y0 = std::max<int64_t>(0, g.y0);
      g.x1 = std::min(n_, g.x1), g.y1 = std::min(n_, g.y1);
    }
    return g;
  }

  // The largest area among the stages first, first + 2, ... up to last.
  static size_t stage_area(const std::vector<Region>& need, int first, int last) {
    size_t a = 0;
    for (int s = first; s <= last; s += 2) a = std::max(a, size_t(need[size_t(s)].nx()) * size_t(need[size_t(s)].ny()));
    return a;
  }

  static Grid view(const Grid& g, const Region& r) {
    const size_t i = size_t((r.x0 - g.r.x0) / g.r.step), j = size_t((r.y0 - g.r.y0) / g.r.step);
    return Grid{r, g.p + j * g.stride + i, g.stride};
  }

  // The grid the first refined stage starts from: the corners, or the
  // reference grid standing for stages 1..m.
  Buffer<float> initial(const Region& r) const {
    Buffer<float> v(size_t(r.nx()) * size_t(r.ny()));
    float g[4];
    gaussian_fill(c_.seed, Counter{0, 0, Stream::kTerrainCorners}, 0, 4, g);
    const float s = float(c_.sigma);
    const int m = c_.reference ? (1 << c_.ref_levels) + 1 : 0;
    for (int j = 0; j < r.ny(); ++j)
      for (int i = 0; i < r.nx(); ++i) {
        const int64_t x = canon(r.x0 + i * r.step), y = canon(r.y0 + j * r.step);
        float& o = v[size_t(j) * size_t(r.nx()) + size_t(i)];
        if (c_.reference) o = c_.reference[size_t(y / ref_step_) * size_t(m) + size_t(x / ref_step_)];
        else if (c_.periodic) o = s * g[0];
        else o = s * g[(x == n_ ? 1 : 0) + (y == n_ ? 2 : 0)];
      }
    return v;
  }

  // N(0, 1) draws for `count` consecutive points of a row from index
  // `first`; periodic rows wrap around after `period` indices.
  void draws(const Counter& counter, int64_t first, int count, int64_t period, float* g) const {
    if (!c_.periodic) return gaussian_fill(c_.seed, counter, uint64_t(first), size_t(count), g);
    int64_t index = first % period;
    while (count > 0) {
      const int chunk = int(std::min<int64_t>(count, period - index));
      gaussian_fill(c_.seed, counter, uint64_t(index), size_t(chunk), g);
      g += chunk, count -= chunk, index = 0;
    }
  }

  bool pinned(int64_t x, int64_t y) const { return ref_step_ != 0 && x % ref_step_ == 0 && y % ref_step_ == 0; }

  // Plain midpoint, stage s: the points of f.r (spacing half) from the
  // coarse grid c (spacing big = 2 half, c.r grown from f.r), written to f.
  //
  // Row by row, as the whole-grid refiner fuses its steps: the fine rows
  // pass through a few scratch rows (the span of grid rows around f.r, one
  // fine point beyond it on each side, the square centres its border
  // diamond points read), and the rows inside f.r are copied out. A grid
  // row k is finished when the centre rows on both sides of it are done;
  // rows of a thread's band start one grid row early. Every point reads the
  // values, and is computed by the arithmetic, it gets in the whole grid.
  void midpoint_stage(const Grid& c, int s, const Grid& f, float square_delta, float diamond_delta) const {
    const int64_t big = c.r.step, half = big / 2;
    const Region& r = f.r;
    Region e{floor_div(r.x0 - half, big) * big, ceil_div(r.x1 + half, big) * big, floor_div(r.y0 - half, big) * big,
             ceil_div(r.y1 + half, big) * big, half};
    if (!c_.periodic) {
      e.x0 = std::max<int64_t>(0, e.x0), e.y0 = std::max<int64_t>(0, e.y0);
      e.x1 = std::min(n_, e.x1), e.y1 = std::min(n_, e.y1);
    }
    const int en = e.nx(), cn = (en + 1) / 2, rows = int((e.y1 - e.y0) / big);  // grid rows 0..rows
    const int copy0 = int((r.x0 - e.x0) / half), copy_n = r.nx();
    const size_t ci0 = size_t((e.x0 - c.r.x0) / big);
    const int64_t cj0 = (e.y0 - c.r.y0) / big;
    const int team = size_t(en) * size_t(2 * rows + 1) >= (size_t(1) << 16) ? threads_ : 1;

#pragma omp parallel num_threads(team)
    {
      const int parts = omp_get_num_threads(), id = omp_get_thread_num();
      const int k0 = int(int64_t(rows + 1) * id / parts), k1 = int(int64_t(rows + 1) * (id + 1) / parts);
      std::vector<float> scratch(size_t(en) * 4 + 8), g(size_t(cn) + 8);
      float *grid = scratch.data(), *next = grid + en, *above = next + en, *below = above + en;
      auto expand = [&](float* row, int k) {
        const float* src = c.row(int(cj0 + k)) + ci0;
        for (int i = 0; i < cn; ++i) row[2 * i] = src[i];
      };
      auto emit = [&](const float* row, int64_t y) {
        if (y >= r.y0 && y <= r.y1) std::copy_n(row + copy0, copy_n, f.row(int((y - r.y0) / half)));
      };
      // The centre row between grid rows up and dn (k - 1 and k): its
      // centres, and unless only those are asked for (the row above a
      // band, which the band before emits), its diamond points if it lies
      // in the region.
      auto centre_row = [&](float* row, const float* up, const float* dn, int k, bool centres_only) {
        const int64_t y = e.y0 + k * big - half;
        const uint32_t cy = detail::stage_row(canon(y), half);
        draws(Counter{cy, uint32_t(s), Stream::kTerrainSquare}, (canon(e.x0 + half) - half) / big, cn - 1,
              n_ / big, g.data());
        detail::square_row(row, up, dn, 1, cn - 1, 2, 1, square_delta, g.data());
        if (centres_only || y < r.y0 || y > r.y1) return;
        draws(Counter{cy, uint32_t(s), Stream::kTerrainDiamond}, canon(e.x0) / big, cn, n_ / big, g.data());
        if (cn > 2) detail::diamond_interior(row, up, dn, 2, cn - 2, 2, 1, diamond_delta, g.data() + 1);
        // The end points: a terrain border has 3 neighbours; elsewhere the
        // left or right centre is outside e, and the point outside f.r.
        if (!c_.periodic && e.x0 == 0) row[0] = detail::border_mean(nullptr, row + 1, up, dn) + diamond_delta * g[0];
        if (!c_.periodic && e.x1 == n_ && cn > 1)
          row[en - 1] = detail::border_mean(row + en - 2, nullptr, up + en - 1, dn + en - 1) + diamond_delta * g[cn - 1];
        emit(row, y);
      };
      // Grid row k's diamond points, between its coarse points, from the
      // centre rows above and below (nullptr: none computed).
      auto finish_grid = [&](float* row, const float* up, const float* dn, int k) {
        const int64_t y = e.y0 + k * big;
        if (y < r.y0 || y > r.y1) return;
        if (cn > 1) {
          draws(Counter{detail::stage_row(canon(y), half), uint32_t(s), Stream::kTerrainDiamond},
                (canon(e.x0 + half) - half) / big, cn - 1, n_ / big, g.data());
          if (up && dn) {
            detail::diamond_interior(row, up, dn, 1, cn - 1, 2, 1, diamond_delta, g.data());
          } else {  // the terrain's top or bottom border (f.r never reaches past e otherwise)
            for (int i = 0; i < cn - 1; ++i)
              row[2 * i + 1] = detail::border_mean(row + 2 * i, row + 2 * i + 2, up ? up + 2 * i + 1 : nullptr,
                                                   dn ? dn + 2 * i + 1 : nullptr) +
                               diamond_delta * g[i];
          }
        }
        emit(row, y);
      };
      if (k0 < k1) {
        bool have_above = false;
        if (k0 > 0) {
          expand(next, k0 - 1);
          expand(grid, k0);
          centre_row(above, next, grid, k0, true);
          have_above = true;
        } else {
          expand(grid, k0);
        }
        for (int k = k0; k < k1; ++k) {
          const bool have_below = k < rows;
          if (have_below) {
            expand(next, k + 1);
            centre_row(below, grid, next, k + 1, false);
          }
          finish_grid(grid, have_above ? above : nullptr, have_below ? below : nullptr, k);
          std::swap(grid, next);
          std::swap(above, below);
          have_above = have_below;
        }
      }
    }
  }

  // Stage s over the coarse grid's whole region, into a new array of half
  // its spacing. Points whose neighbours lie outside the region (and not
  // outside the terrain) cannot be computed and are left NaN: the region
  // was grown so that none of them is needed.
  Buffer<float> refine(const Grid& c, int s, float square_delta, float diamond_delta) {
    const int64_t big = c.r.step, half = big / 2, cells = n_ / big;
    const int cnx = c.r.nx(), cny = c.r.ny(), nx = 2 * cnx - 1, ny = 2 * cny - 1;
    const int64_t X0 = c.r.x0, Y0 = c.r.y0;
    Buffer<float> f(size_t(nx) * size_t(ny));
    float* F = f.data();
    auto row = [&](int j) { return F + size_t(j) * size_t(nx); };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int team = size_t(nx) * size_t(ny) >= (size_t(1) << 16) ? threads_ : 1;
    const bool additions = c_.additions;

#pragma omp parallel num_threads(team)
    {
      std::vector<float> g(size_t(nx) + 8);
      // The coarse points at the even places, NaN between them.
#pragma omp for schedule(static)
      for (int j = 0; j < ny; ++j) {
        float* r = row(j);
        if (j % 2) {
          std::fill_n(r, nx, nan);
        } else {
          const float* src = c.row(j / 2);
          for (int i = 0; i < cnx; ++i) r[2 * i] = src[i];
          for (int i = 1; i < nx; i += 2) r[i] = nan;
        }
      }
      // Square step: every centre has its 4 corners in the region.
#pragma omp for schedule(static)
      for (int j = 1; j < ny; j += 2) {
        const int64_t y = Y0 + j * half;
        draws(Counter{detail::stage_row(canon(y), half), uint32_t(s), Stream::kTerrainSquare},
              (canon(X0 + half) - half) / big, cnx - 1, cells, g.data());
        detail::square_row(row(j), row(j - 1), row(j + 1), 1, cnx - 1, 2, 1, square_delta, g.data());
      }
      if (additions) add(0, 0, 2, square_delta, s, Stream::kTerrainAddOld, X0, Y0, half, nx, ny, F, g.data());
      // Diamond step.
#pragma omp for schedule(static)
      for (int j = 0; j < ny; ++j) diamond_row(j, s, X0, Y0, half, nx, ny, F, diamond_delta, g.data());
      if (additions) {
        add(0, 0, 2, diamond_delta, s, Stream::kTerrainAddNew, X0, Y0, half, nx, ny, F, g.data());
        add(1, 1, 2, diamond_delta, s, Stream::kTerrainAddHalf, X0, Y0, half, nx, ny, F, g.data());
      }
    }
    return f;
  }

  // The diamond points of local row j: on a grid row (j even) the odd
  // places, on a centre row the even ones.
  void diamond_row(int j, int s, int64_t X0, int64_t Y0, int64_t half, int nx, int ny, float* F, float delta,
                   float* g) const {
    const int64_t big = 2 * half, cells = n_ / big, y = Y0 + j * half;
    const bool grid_row = j % 2 == 0;
    // Whether a neighbour is outside the terrain (a border), and whether it
    // is missing from the region although it exists (then nothing here is
    // computable).
    const bool up_out = !c_.periodic && y - half < 0, dn_out = !c_.periodic && y + half > n_;
    if ((j == 0 && !up_out) || (j == ny - 1 && !dn_out)) return;
    float* r = F + size_t(j) * size_t(nx);
    const float* up = up_out ? nullptr : r - nx;
    const float* dn = dn_out ? nullptr : r + nx;
    const int i0 = grid_row ? 1 : 0;
    const int count = (nx - 1 - i0) / 2 + 1;
    const int64_t x_first = X0 + i0 * half;
    const int64_t first = grid_row ? (canon(x_first) - half) / big : canon(x_first) / big;
    draws(Counter{detail::stage_row(canon(y), half), uint32_t(s), Stream::kTerrainDiamond}, first, count, cells, g);
    // Interior places (both horizontal neighbours in the region) on a row
    // with both vertical ones: the hot loop.
    int lo = i0 == 0 ? 1 : 0, hi = count;
    if (i0 + 2 * (count - 1) == nx - 1) --hi;
    if (up && dn && hi > lo) detail::diamond_interior(r, up, dn, i0 + 2 * lo, hi - lo, 2, 1, delta, g + lo);
    for (int k = 0; k < count; ++k) {
      if (up && dn && k >= lo && k < hi) continue;
      const int i = i0 + 2 * k;
      const int64_t x = X0 + i * half;
      const bool left_out = !c_.periodic && x - half < 0, right_out = !c_.periodic && x + half > n_;
      if ((i == 0 && !left_out) || (i == nx - 1 && !right_out)) continue;
      r[i] = detail::border_mean(left_out ? nullptr : r + i - 1, right_out ? nullptr : r + i + 1,
                                 up ? up + i : nullptr, dn ? dn + i : nullptr) +
             delta * g[k];
    }
  }

  // Feder's additions to the places (i0 + step k, j0 + step l) of the local
  // array (reference nodes stay as given). Called inside a parallel region.
  void add(int i0, int j0, int step, float delta, int s, Stream stream, int64_t X0, int64_t Y0, int64_t half,
           int nx, int ny, float* F, float* g) const {
    const int64_t big = 2 * half, cells = n_ / big, origin = i0 == 0 ? 0 : half;
    const int count = (nx - 1 - i0) / step + 1;
#pragma omp for schedule(static)
    for (int j = j0; j < ny; j += step) {
      const int64_t y = canon(Y0 + j * half);
      draws(Counter{uint32_t((y - origin) / big), uint32_t(s), stream}, (canon(X0 + i0 * half) - origin) / big, count,
            cells, g);
      float* r = F + size_t(j) * size_t(nx);
      for (int k = 0; k < count; ++k) {
        const int i = i0 + k * step;
        if (!pinned(canon(X0 + i * half), y)) r[i] += delta * g[k];
      }
    }
  }

  const DiamondSquareConfig& c_;
  const int64_t n_;
  const int target_;
  const int threads_;
  int first_ = 1;
  int64_t ref_step_ = 0;
};

}  // namespace

Heightfield diamond_square_window(const DiamondSquareConfig& config, const Window& window, int lod) {
  Heightfield hf(window.width, window.height);
  if (lod == 0 || !config.additions) {
    WindowRefiner(config, config.levels - lod).run(window, hf.data());
    return hf;
  }
  // Additions move old points at every stage: refine the footprint at full
  // resolution, then keep every 2^lod-th point.
  const int64_t k = int64_t(1) << lod;
  const Window full{window.x0 * k, window.y0 * k, int32_t((window.width - 1) * k + 1),
                    int32_t((window.height - 1) * k + 1)};
  const Heightfield whole = diamond_square_window(config, full, 0);
  for (int j = 0; j < window.height; ++j)
    for (int i = 0; i < window.width; ++i)
      hf.data()[size_t(j) * size_t(window.width) + size_t(i)] =
          whole.data()[size_t(j * k) * size_t(full.width) + size_t(i * k)];
  return hf;
}

}  // namespace ft::terrain
