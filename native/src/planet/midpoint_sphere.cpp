// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/midpoint_sphere.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "planet/cube_sphere.hpp"

namespace ft::planet {

void FaceRect::add(int64_t x, int64_t y) {
  if (empty()) {
    x0 = x1 = x, y0 = y1 = y;
    return;
  }
  x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
}

void FaceRect::add(const FaceRect& r) {
  if (r.empty()) return;
  add(r.x0, r.y0);
  add(r.x1, r.y1);
}

namespace {

int64_t floor_half(int64_t a) { return a >= 0 ? a / 2 : -((1 - a) / 2); }
int64_t ceil_half(int64_t a) { return -floor_half(-a); }
int64_t odd_up(int64_t a) { return (a & 1) ? a : a + 1; }
int64_t odd_down(int64_t a) { return (a & 1) ? a : a - 1; }

// The samples one level down that computing rect `r` of face f at N = n
// reads: the cell corners around it on f, and where r reaches an edge, the
// corners of the cell centres one row past it, which lie one row onto the
// next face (an edge vertex's parents are a centre on each face).
void add_parents(int f, const FaceRect& r, int64_t n, FaceRects* below) {
  const int64_t h = n / 2;
  const int64_t a = ceil_half(std::max<int64_t>(r.x0 - 2, 0)), b = floor_half(std::min(r.x1 + 2, n));
  const int64_t c = ceil_half(std::max<int64_t>(r.y0 - 2, 0)), d = floor_half(std::min(r.y1 + 2, n));
  (*below)[size_t(f)].add(a, c);
  (*below)[size_t(f)].add(b, d);
  // A row past an edge is a row of the next face, but its ends may lie on
  // a third face's edge too, where locate() takes the first face: each point
  // goes to the face its lookup in refine() will read.
  auto fold = [&](int64_t i, int64_t j) {
    int64_t gi, gj;
    const int g = locate(folded_point(f, i, j, h), h, &gi, &gj);
    (*below)[size_t(g)].add(gi, gj);
  };
  for (int64_t j = c; j <= d; ++j) {
    if (r.x0 == 0) fold(-1, j);
    if (r.x1 == n) fold(h + 1, j);
  }
  for (int64_t i = a; i <= b; ++i) {
    if (r.y0 == 0) fold(i, -1);
    if (r.y1 == n) fold(i, h + 1);
  }
}

// need[L]: the samples of each face computed at level L.
std::vector<FaceRects> requirements(int level, const FaceRects& rects) {
  std::vector<FaceRects> need(size_t(level) + 1);
  need[size_t(level)] = rects;
  for (int L = level; L >= 1; --L)
    for (int f = 0; f < 6; ++f)
      if (!need[size_t(L)][size_t(f)].empty()) add_parents(f, need[size_t(L)][size_t(f)], int64_t(1) << L, &need[size_t(L) - 1]);
  return need;
}

int64_t total(const FaceRects& r) {
  int64_t s = 0;
  for (const FaceRect& x : r) s += x.count();
  return s;
}

// One face's samples of one level, in double: 23 levels of means and
// displacements 2^-18 of sigma stay exact to well below a millimetre.
struct Grid {
  FaceRect r;
  std::vector<double> v;
  void allocate(const FaceRect& rect) {
    r = rect;
    v.assign(size_t(r.count()), 0.0);
  }
  double at(int64_t i, int64_t j) const {
    if (i < r.x0 || i > r.x1 || j < r.y0 || j > r.y1)
      fail(FT_ERR_INTERNAL, "midpoint sphere: sample (" + std::to_string(i) + ", " + std::to_string(j) +
                                ") was not computed");
    return v[size_t((j - r.y0) * r.width() + (i - r.x0))];
  }
};
using Grids = std::array<Grid, 6>;

// The displacement of the vertex born at level L at cube point p (N = 2^L).
class Displacer {
 public:
  Displacer(const MidpointConfig& c, int level) : seed_(c.seed), power_(-0.75 * c.hurst) {
    const double n = std::ldexp(1.0, level), unit = c.sigma * kMidpointUnit, side = 2.0 / n;
    n2_ = n * n;
    edge_ = unit * std::pow(side, c.hurst);
    centre_ = unit * std::pow(side * std::sqrt(2.0), c.hurst);
  }
  // 1 + s^2 + t^2 = |p|^2 / N^2, exact in int64 (|p|^2 <= 3 2^52).
  double operator()(const CubePoint& p, bool centre) const {
    const double local = std::pow(double(p.x * p.x + p.y * p.y + p.z * p.z) / n2_, power_);
    return (centre ? centre_ : edge_) * local * double(gaussian(seed_, p));
  }
  static float gaussian(uint64_t seed, const CubePoint& p) {
    return gaussian_at(seed, Counter{uint32_t(p.y), uint32_t(p.z), Stream::kPlanetMidpoint},
                       uint64_t(uint32_t(p.x)) << 2);
  }

 private:
  uint64_t seed_;
  double power_, n2_ = 1, edge_ = 0, centre_ = 0;
};

// rows(k) for k in 0..count-1 on `team` threads; the caller's thread reports
// done / all of the whole computation and takes a cancel; an exception
// stops the rest and is rethrown.
template <class Rows>
void parallel_rows(int64_t count, int team, const Progress& progress, int64_t* done, int64_t all, int64_t per_row,
                   Rows&& rows) {
  std::atomic<bool> stop{false};
  std::atomic<int64_t> finished{0};
  std::exception_ptr error;
  const int64_t start = *done;
  // Small passes run on one thread: waking a team costs more than they do,
  // and on a busy machine each region can wait a time slice for a
  // descheduled worker (a level-7 cube-sphere is 2 x 6 x 7 regions: 0.1 s
  // alone, 2 s at load 9). The output never depends on it.
  if (count * per_row < (int64_t(1) << 16)) team = 1;
#pragma omp parallel for num_threads(team) schedule(dynamic, 4)
  for (int64_t k = 0; k < count; ++k) {
    if (stop.load(std::memory_order_relaxed)) continue;
    try {
      rows(k);
      const int64_t d = finished.fetch_add(1, std::memory_order_relaxed) + 1;
      // `all` counts a level's cell centres as a quarter of its samples; the
      // rims they have past a rect's edges can take the sum a little past it.
      if (omp_get_thread_num() == 0) progress.report(std::min(1.0, double(start + d * per_row) / double(all)));
    } catch (...) {
#pragma omp critical(ft_midpoint_sphere)
      if (!error) error = std::current_exception();
      stop.store(true);
    }
  }
  if (error) std::rethrow_exception(error);
  *done = start + count * per_row;
}

// Level L of face f over rect r from level L - 1 (`below`, every face).
void refine(const Displacer& disp, int64_t n, int f, const FaceRect& r, const Grids& below, int team,
            const Progress& progress, int64_t* done, int64_t all, Grid* out) {
  const int64_t h = n / 2;
  const Grid& mine = below[size_t(f)];
  // A cell corner (i, j) at N = h, up to one row past an edge of f.
  auto corner = [&](int64_t i, int64_t j) {
    if (i >= 0 && i <= h && j >= 0 && j <= h) return mine.at(i, j);
    int64_t gi, gj;
    const int g = locate(folded_point(f, i, j, h), h, &gi, &gj);
    return below[size_t(g)].at(gi, gj);
  };
  // Cell centres (odd, odd) around r, one past an edge where r reaches it.
  const int64_t cx0 = odd_up(r.x0 - 1), cx1 = odd_down(r.x1 + 1), cy0 = odd_up(r.y0 - 1), cy1 = odd_down(r.y1 + 1);
  const int64_t cw = (cx1 - cx0) / 2 + 1, ch = (cy1 - cy0) / 2 + 1;
  std::vector<double> centres(size_t(cw * ch), 0.0);
  parallel_rows(ch, team, progress, done, all, cw, [&](int64_t k) {
    const int64_t j = cy0 + 2 * k;
    for (int64_t m = 0; m < cw; ++m) {
      const int64_t i = cx0 + 2 * m;
      if ((i < 0 || i > n) && (j < 0 || j > n)) continue;  // no cube point: past two edges at once
      // Opposite corners in pairs: the same sums on every face.
      const double mean = 0.25 * ((corner((i - 1) / 2, (j - 1) / 2) + corner((i + 1) / 2, (j + 1) / 2)) +
                                  (corner((i + 1) / 2, (j - 1) / 2) + corner((i - 1) / 2, (j + 1) / 2)));
      centres[size_t(k * cw + m)] = mean + disp(folded_point(f, i, j, n), true);
    }
  });
  auto centre = [&](int64_t i, int64_t j) { return centres[size_t(((j - cy0) / 2) * cw + (i - cx0) / 2)]; };
  out->allocate(r);
  const int64_t w = r.width();
  parallel_rows(r.height(), team, progress, done, all, w, [&](int64_t k) {
    const int64_t j = r.y0 + k;
    double* row = out->v.data() + k * w;
    for (int64_t i = r.x0; i <= r.x1; ++i) {
      const bool odd_i = i & 1, odd_j = j & 1;
      double v;
      if (!odd_i && !odd_j) {
        v = mine.at(i / 2, j / 2);
      } else if (odd_i && odd_j) {
        v = centre(i, j);
      } else {
        // A side's middle: its two ends, then the two centres beside it.
        const double ends = odd_i ? mine.at((i - 1) / 2, j / 2) + mine.at((i + 1) / 2, j / 2)
                                  : mine.at(i / 2, (j - 1) / 2) + mine.at(i / 2, (j + 1) / 2);
        const double sides = odd_i ? centre(i, j - 1) + centre(i, j + 1) : centre(i - 1, j) + centre(i + 1, j);
        v = 0.25 * (ends + sides) + disp(cube_point(f, i, j, n), false);
      }
      row[i - r.x0] = v;
    }
  });
}

}  // namespace

uint64_t midpoint_work_bytes(int level, const FaceRects& rects) {
  const std::vector<FaceRects> need = requirements(level, rects);
  // Two levels at once, and the finer one's centres (a quarter, plus a rim).
  uint64_t peak = 0;
  for (int L = 1; L <= level; ++L) {
    int64_t rim = 0;
    for (const FaceRect& r : need[size_t(L)])
      if (!r.empty()) rim += 2 * (r.width() + r.height()) + 8;
    const uint64_t samples = uint64_t(total(need[size_t(L)]) + total(need[size_t(L) - 1])) +
                             uint64_t(total(need[size_t(L)]) / 4 + rim);
    peak = std::max(peak, samples);
  }
  return checked_bytes(std::max<uint64_t>(peak, 8), sizeof(double));
}

void midpoint_faces(const MidpointConfig& c, int level, const FaceRects& rects, const std::array<float*, 6>& out,
                    int threads, const Progress& progress) {
  check_int_range("level", level, 0, kMaxLevel);
  for (int f = 0; f < 6; ++f) {
    const FaceRect& r = rects[size_t(f)];
    const int64_t n = int64_t(1) << level;
    if (!r.empty() && (r.x0 < 0 || r.y0 < 0 || r.x1 > n || r.y1 > n))
      fail(FT_ERR_INTERNAL, "midpoint sphere: a rect outside face " + std::to_string(f));
  }
  check_allocation(midpoint_work_bytes(level, rects), "the coarser levels of a midpoint planet's samples");
  const std::vector<FaceRects> need = requirements(level, rects);
  const int team = resolve_threads(threads);
  int64_t all = 1, done = 0;
  for (const FaceRects& r : need) all += total(r) * 5 / 4;
  Grids below;
  for (int f = 0; f < 6; ++f) {
    const FaceRect& r = need[0][size_t(f)];
    if (r.empty()) continue;
    below[size_t(f)].allocate(r);
    for (int64_t j = r.y0; j <= r.y1; ++j)
      for (int64_t i = r.x0; i <= r.x1; ++i)
        below[size_t(f)].v[size_t((j - r.y0) * r.width() + (i - r.x0))] =
            c.sigma * kMidpointUnit * double(Displacer::gaussian(c.seed, cube_point(f, i, j, 1)));
  }
  for (int L = 1; L <= level; ++L) {
    const Displacer disp(c, L);
    Grids here;
    for (int f = 0; f < 6; ++f) {
      const FaceRect& r = need[size_t(L)][size_t(f)];
      if (!r.empty()) refine(disp, int64_t(1) << L, f, r, below, team, progress, &done, all, &here[size_t(f)]);
    }
    below = std::move(here);
  }
  for (int f = 0; f < 6; ++f) {
    const std::vector<double>& v = below[size_t(f)].v;
    if (!rects[size_t(f)].empty()) std::transform(v.begin(), v.end(), out[size_t(f)], [](double x) { return float(x); });
  }
  progress.report(1.0);
}

}  // namespace ft::planet
