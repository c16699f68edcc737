// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/mandelbrot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace ft::terrain {
namespace {

// |z|^2 beyond which the smooth count is read: |z| > 2^16, where the
// neglected |c| / |z|^2 term is below 2^-31 (the count's jump at n is then
// under 1e-9 of an iteration).
constexpr double kSmoothRadius2 = 0x1p32;
// Steps allowed from |z| > 2 to |z| > 2^16. From |z| = 2 + e the modulus
// grows at least like 2 + 4^k e, so only points within ~4^-100 of the
// escape circle could need more; they keep the count they reached.
constexpr int32_t kMaxSmoothSteps = 128;

// One step z <- z^2 + c, written once so that the terrain and escape_time
// do exactly the same arithmetic (x^2 - y^2 + cx; 2xy + cy).
inline void step(double& x, double& y, double cx, double cy) {
  const double nx = x * x - y * y + cx;
  y = 2.0 * x * y + cy;
  x = nx;
}

// The smooth count from the step n at which |z|^2 = r2 first exceeded
// kSmoothRadius2: n - log2(log2 |z_n|), log2 |z| = log2(|z|^2) / 2.
inline double smooth_count(int32_t n, double r2) { return double(n) - std::log2(0.5 * std::log2(r2)); }

// Known interior: the main cardioid and the period-2 disc (|c + 1| <= 1/4),
// which hold most of the set's area in a whole view. Their points never
// escape, so skipping their iterations changes no height.
inline bool in_cardioid_or_bulb(double cx, double cy) {
  const double xq = cx - 0.25, y2 = cy * cy;
  const double q = xq * xq + y2;
  if (q * (q + xq) <= 0.25 * y2) return true;
  const double xb = cx + 1.0;
  return xb * xb + y2 <= 0.0625;
}

// Three significant digits: the sizes in the precision message.
std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// ulp(v) for v > 0: the spacing of doubles at v.
double ulp_of(double v) { return std::ldexp(1.0, std::ilogb(v) - 52); }

// The largest coordinate magnitude the window reaches, and at least 2, the
// radius of the disc every iterate stays in until it escapes.
double coordinate_scale(int32_t width, int32_t height, double cx, double cy, double step) {
  const double half_w = 0.5 * double(width - 1) * step, half_h = 0.5 * double(height - 1) * step;
  return std::max({2.0, std::fabs(cx) + half_w, std::fabs(cy) + half_h});
}

}  // namespace

EscapeTime escape_time(double cx, double cy, int32_t iterations) {
  EscapeTime e;
  double x = 0.0, y = 0.0, r2 = 0.0;
  int32_t n = 0;
  while (n < iterations) {
    step(x, y, cx, cy);
    ++n;
    r2 = x * x + y * y;
    if (r2 > 4.0) break;
  }
  if (!(r2 > 4.0)) {
    e.count = iterations;
    e.inside = true;
    return e;
  }
  e.count = n;
  for (int32_t k = 0; r2 <= kSmoothRadius2 && k < kMaxSmoothSteps; ++k) {
    step(x, y, cx, cy);
    ++n;
    r2 = x * x + y * y;
  }
  e.smooth = smooth_count(n, r2);
  return e;
}

double mandelbrot_height(double nu, double sigma) {
  // s = log2(1 + 2^nu), written so that neither branch overflows.
  constexpr double kLn2 = 0.69314718055994530942;
  const double s = nu > 0 ? nu + std::log1p(std::exp2(-nu)) / kLn2 : std::log1p(std::exp2(nu)) / kLn2;
  return sigma * (1.0 - 1.0 / std::sqrt(1.0 + s));
}

double mandelbrot_spacing(int32_t width, double zoom) { return 4.0 / (zoom * double(width - 1)); }

double mandelbrot_max_zoom(int32_t width, double center_x, double center_y) {
  // At the limit the window is tiny, so the coordinate scale is that of the
  // centre (or 2); the zoom follows from step >= kMinUlps * ulp(scale).
  const double scale = std::max({2.0, std::fabs(center_x), std::fabs(center_y)});
  return 4.0 / (double(width - 1) * kMandelbrotMinUlps * ulp_of(scale));
}

void validate_mandelbrot(const MandelbrotConfig& c, int64_t max_side) {
  check_int_range("width", c.width, 2, max_side);
  check_int_range("height", c.height, 2, max_side);
  check_range("center_x", c.center_x, -kMandelbrotCenterLimit, kMandelbrotCenterLimit);
  check_range("center_y", c.center_y, -kMandelbrotCenterLimit, kMandelbrotCenterLimit);
  if (!(c.zoom >= kMandelbrotMinZoom) || !std::isfinite(c.zoom))
    invalid("zoom must be a finite number >= " + format_number(kMandelbrotMinZoom) +
            " (the width spans 4 / zoom of the complex plane), got " + format_number(c.zoom));
  check_int_range("iterations", c.iterations, 1, kMaxMandelbrotIterations);
  check_positive("sigma", c.sigma);
  check_int_range("supersample", c.supersample, 1, kMaxMandelbrotSupersample);
  const double step = mandelbrot_spacing(c.width, c.zoom);
  const double scale = coordinate_scale(c.width, c.height, c.center_x, c.center_y, step);
  const double need = kMandelbrotMinUlps * ulp_of(scale);
  if (step < need) {
    invalid("zoom " + short_number(c.zoom) + " is beyond double precision: " + std::to_string(c.width) +
            " samples across put neighbours " + short_number(step) + " apart, but near |c| = " +
            short_number(scale) + " doubles are " + short_number(ulp_of(scale)) +
            " apart and samples need at least 64 of them between neighbours (" + short_number(need) +
            "); for this width and centre the zoom can reach " +
            short_number(mandelbrot_max_zoom(c.width, c.center_x, c.center_y)) +
            " (fewer samples across allow a deeper zoom)");
  }
}

Heightfield mandelbrot(const MandelbrotConfig& c) { return mandelbrot_window(c, 0, 0, c.width, c.height); }

Heightfield mandelbrot_window(const MandelbrotConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h) {
  Heightfield hf(w, h);
  const int threads = resolve_threads(c.threads);
  const double step = mandelbrot_spacing(c.width, c.zoom);
  // Each sample's c is one rounding of (centre + offset * step), the offset
  // computed from the sample's global index alone (integers and halves below
  // 2^53 are exact): the same bits whichever window asks for it.
  const double mid_x = 0.5 * double(c.width - 1), mid_y = 0.5 * double(c.height - 1);
  // The escape time grows without bound towards the set; the set's own
  // height is the limit the height map approaches there (escape time
  // saturated at `iterations`), so the set is a plateau the slopes meet.
  const double top = double(c.iterations);
  const double inside = mandelbrot_height(top, c.sigma);
  // k x k points per sample, at the centres of a k x k split of the sample's
  // cell, averaged in a fixed order: near the boundary the escape time
  // changes faster than the samples, and one point per sample gives needles.
  const int k = c.supersample;
  std::vector<double> split(static_cast<size_t>(k));
  for (int a = 0; a < k; ++a) split[size_t(a)] = (a + 0.5) / k - 0.5;
  const double weight = 1.0 / double(k * k);
  // Rows in blocks, so that progress (and cancellation) is reported from the
  // calling thread between them; a block is big enough to keep every thread
  // busy and small enough to answer a cancel within a fraction of a second.
  const int32_t block = std::max(8, 4 * threads);
  for (int32_t first = 0; first < h; first += block) {
    const int32_t last = std::min(h, first + block);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (int32_t j = first; j < last; ++j) {
      float* row = hf.data() + size_t(j) * size_t(w);
      const double gy = double(y0 + j) - mid_y;
      for (int32_t i = 0; i < w; ++i) {
        const double gx = double(x0 + i) - mid_x;
        double sum = 0.0;
        for (int b = 0; b < k; ++b) {
          const double cy = c.center_y - (gy + split[size_t(b)]) * step;
          for (int a = 0; a < k; ++a) {
            const double cx = c.center_x + (gx + split[size_t(a)]) * step;
            if (in_cardioid_or_bulb(cx, cy)) {
              sum += inside;
              continue;
            }
            const EscapeTime e = escape_time(cx, cy, c.iterations);
            sum += e.inside ? inside : mandelbrot_height(std::min(e.smooth, top), c.sigma);
          }
        }
        row[i] = float(k == 1 ? sum : sum * weight);
      }
    }
    c.progress.report(double(last) / double(h));
  }
  return hf;
}

}  // namespace ft::terrain
