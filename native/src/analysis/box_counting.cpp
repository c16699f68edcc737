// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/box_counting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace ft::analysis {
namespace {

struct Bounds {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
};

Bounds bounds_of(const PolylineSet& set) {
  Bounds b;
  for (const Vec3& p : set.points) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
      invalid("box counting needs finite x, y coordinates");
    b.x0 = std::min(b.x0, p[0]), b.x1 = std::max(b.x1, p[0]);
    b.y0 = std::min(b.y0, p[1]), b.y1 = std::max(b.y1, p[1]);
  }
  return b;
}

double median_segment_length(const PolylineSet& set) {
  std::vector<double> len;
  len.reserve(set.points.size());
  for (int64_t i = 0; i < set.line_count(); ++i)
    for (int64_t v = set.line_begin(i) + 1; v < set.line_end(i); ++v) {
      const Vec3& a = set.points[size_t(v - 1)];
      const Vec3& b = set.points[size_t(v)];
      const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
      if (l > 0) len.push_back(l);
    }
  if (len.empty()) return 0.0;
  auto mid = len.begin() + std::ptrdiff_t(len.size() / 2);
  std::nth_element(len.begin(), mid, len.end());
  return *mid;
}

inline uint64_t cell_key(int64_t ix, int64_t iy) {
  return (uint64_t(ix) << 32) ^ (uint64_t(iy) & 0xffffffffu);
}

// Appends the keys of every grid cell the segment (u0, v0) - (u1, v1) passes
// through, in grid units (cell (i, j) is [i, i+1) x [j, j+1)). A DDA walk
// (Amanatides & Woo) that is forced to stop in the end point's cell: once a
// coordinate has reached its final cell it no longer steps, so rounding in
// the crossing parameters can never walk past the end or loop.
void walk_segment(double u0, double v0, double u1, double v1, std::vector<uint64_t>& keys) {
  int64_t ix = int64_t(std::floor(u0)), iy = int64_t(std::floor(v0));
  const int64_t jx = int64_t(std::floor(u1)), jy = int64_t(std::floor(v1));
  keys.push_back(cell_key(ix, iy));
  if (ix == jx && iy == jy) return;
  const double du = u1 - u0, dv = v1 - v0;
  const int64_t sx = jx > ix ? 1 : -1, sy = jy > iy ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  double tx = du != 0 ? ((double(ix) + (sx > 0 ? 1.0 : 0.0)) - u0) / du : inf;
  double ty = dv != 0 ? ((double(iy) + (sy > 0 ? 1.0 : 0.0)) - v0) / dv : inf;
  const double dtx = du != 0 ? 1.0 / std::fabs(du) : inf;
  const double dty = dv != 0 ? 1.0 / std::fabs(dv) : inf;
  while (ix != jx || iy != jy) {
    const bool step_x = iy == jy || (ix != jx && tx < ty);
    if (step_x) ix += sx, tx += dtx;
    else iy += sy, ty += dty;
    keys.push_back(cell_key(ix, iy));
  }
}

// Upper bound of the cells the walks visit at box size eps (the key buffer).
double visit_bound(const PolylineSet& set, double eps) {
  double visits = double(set.line_count());
  for (int64_t i = 0; i < set.line_count(); ++i)
    for (int64_t v = set.line_begin(i) + 1; v < set.line_end(i); ++v) {
      const Vec3& a = set.points[size_t(v - 1)];
      const Vec3& b = set.points[size_t(v)];
      visits += (std::fabs(b[0] - a[0]) + std::fabs(b[1] - a[1])) / eps + 1.0;
    }
  return visits;
}

int64_t count_unchecked(const PolylineSet& set, double eps, double ox, double oy, double visits) {
  const double inv = 1.0 / eps;
  std::vector<uint64_t> keys;
  keys.reserve(size_t(visits));
  for (int64_t i = 0; i < set.line_count(); ++i) {
    const int64_t b = set.line_begin(i), e = set.line_end(i);
    if (e - b == 1) {
      const Vec3& p = set.points[size_t(b)];
      keys.push_back(cell_key(int64_t(std::floor((p[0] - ox) * inv)), int64_t(std::floor((p[1] - oy) * inv))));
    }
    for (int64_t v = b + 1; v < e; ++v) {
      const Vec3& p = set.points[size_t(v - 1)];
      const Vec3& q = set.points[size_t(v)];
      walk_segment((p[0] - ox) * inv, (p[1] - oy) * inv, (q[0] - ox) * inv, (q[1] - oy) * inv, keys);
    }
  }
  std::sort(keys.begin(), keys.end());
  return int64_t(std::unique(keys.begin(), keys.end()) - keys.begin());
}

// The cells' indices are floor((coordinate - origin) / eps) as int64: they
// must be finite and within 2^30 of the origin, or the conversion is
// undefined (a fuzz finding: a subnormal box size made 1 / eps infinite).
void check_grid(const Bounds& b, double eps, double ox, double oy) {
  const double reach = std::max({std::fabs(b.x0 - ox), std::fabs(b.x1 - ox), std::fabs(b.y0 - oy), std::fabs(b.y1 - oy)});
  if (!(reach / eps <= double(1 << 30)) || !std::isfinite(1.0 / eps))
    invalid("box size " + format_number(eps) + " does not fit the set's distance " + format_number(reach) +
            " from the grid origin (at most 2^30 boxes, and 1 / size finite)");
}

}  // namespace

int64_t count_boxes(const PolylineSet& set, double eps, double ox, double oy) {
  check_positive("box size", eps);
  check_finite("grid origin x", ox);
  check_finite("grid origin y", oy);
  if (set.points.empty()) return 0;
  check_grid(bounds_of(set), eps, ox, oy);
  const double visits = visit_bound(set, eps);
  check_allocation(uint64_t(visits) * sizeof(uint64_t), "box counting at this box size");
  return count_unchecked(set, eps, ox, oy, visits);
}

SlopeFit fit_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = x.size();
  if (n < 2 || y.size() != n) invalid("a slope fit needs at least 2 (x, y) pairs");
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= double(n), my /= double(n);
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  if (!(sxx > 0)) invalid("a slope fit needs at least 2 distinct x values");
  SlopeFit f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  if (n > 2) {
    double ssr = 0;
    for (size_t i = 0; i < n; ++i) {
      const double r = y[i] - (f.intercept + f.slope * x[i]);
      ssr += r * r;
    }
    f.std_error = std::sqrt(ssr / double(n - 2) / sxx);
  }
  return f;
}

BoxCountResult box_counting_dimension(const PolylineSet& set, const BoxCountOptions& o) {
  if (set.points.empty()) invalid("box counting needs at least one vertex");
  check_int_range("sizes_per_octave", o.sizes_per_octave, 1, 16);
  check_int_range("grid_shifts", o.grid_shifts, 1, 64);
  if (!(o.min_size >= 0) || !std::isfinite(o.min_size)) invalid("min_size must be >= 0 (0: automatic), got " + format_number(o.min_size));
  if (!(o.max_size >= 0) || !std::isfinite(o.max_size)) invalid("max_size must be >= 0 (0: automatic), got " + format_number(o.max_size));
  const Bounds b = bounds_of(set);
  const double extent = std::max(b.x1 - b.x0, b.y1 - b.y0);
  if (!(extent > 0)) invalid("box counting needs a set that is not a single point (its x, y extent is 0)");
  // Vertices near +-1e308 are finite, but their extent is not: every box
  // size would be infinite and the cells' indices out of range (a fuzz finding).
  if (!std::isfinite(extent)) invalid("box counting needs a set whose x, y extent is finite (its vertices span more than 1.8e308)");

  BoxCountResult r;
  r.max_size = o.max_size > 0 ? o.max_size : extent / 4;
  r.min_size = o.min_size > 0 ? o.min_size : std::max(2 * median_segment_length(set), extent / 65536.0);
  if (!(extent / r.min_size <= double(1 << 30)))
    invalid("min_size " + format_number(r.min_size) + " is too small for the extent " + format_number(extent) +
            " (at most 2^30 boxes across)");
  // The origin sits one to two boxes below/left of the set (below): the
  // finest and the coarsest grids both fit.
  for (const double eps : {r.min_size, r.max_size}) check_grid(b, eps, b.x0 - 2 * eps, b.y0 - 2 * eps);

  // One memory check for the finest size; the key buffer is largest there.
  const double finest = visit_bound(set, r.min_size);
  check_allocation(uint64_t(finest) * sizeof(uint64_t), "box counting at box size " + format_number(r.min_size));
  std::vector<double> x, y;
  for (int k = 0;; ++k) {
    const double eps = r.max_size * std::exp2(-double(k) / o.sizes_per_octave);
    if (eps < r.min_size * (1 - 1e-12)) break;
    int64_t best = std::numeric_limits<int64_t>::max();
    for (int s = 0; s < o.grid_shifts; ++s) {
      // The origin sits one box below/left of the set so cells are >= 0.
      const double shift = eps * (1.0 + double(s) / o.grid_shifts);
      best = std::min(best, count_unchecked(set, eps, b.x0 - shift, b.y0 - shift, visit_bound(set, eps)));
    }
    r.sizes.push_back(eps);
    r.counts.push_back(best);
    x.push_back(std::log(1.0 / eps));
    y.push_back(std::log(double(best)));
  }
  if (r.sizes.size() < 3)
    invalid("box counting needs at least 3 box sizes between min_size " + format_number(r.min_size) +
            " and max_size " + format_number(r.max_size) +
            " (for coarse polylines give a smaller min_size, or more sizes_per_octave)");
  const SlopeFit f = fit_slope(x, y);
  r.dimension = f.slope;
  r.std_error = f.std_error;
  return r;
}

}  // namespace ft::analysis
