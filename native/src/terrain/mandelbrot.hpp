// SPDX-License-Identifier: GPL-3.0-or-later
// The Mandelbrot set as a terrain (seed 002: z <- z^2 + c from z = 0, escape
// radius 2, colour by iteration count; Mandelbrot 1980).
//
// Heights are the continuous escape time, not the integer count, so the
// surface has no terraces:
//   nu(c) = n - log2(log2 |z_n|),  n = the first step with |z_n| > 2^16,
// the normalised iteration count (Linas Vepstas 1997; Peitgen & Richter 1986
// for the potential it comes from). Since log2 |z_{n+1}| = 2 log2 |z_n| up to
// a term in |c| / |z_n|^2 < 2^-31, nu does not jump where n does, and
// nu = -log2(G(c) / ln 2) where G is the Douady-Hubbard potential of the set
// (Douady & Hubbard 1982): its level curves are the set's equipotentials.
//
// As a terrain, raw nu is a poor height: it diverges at the boundary (a few
// samples next to a cusp reach hundreds while their neighbours hold 10), and
// it goes negative far away (nu < 0 for |c| above about 2). So the height is
//   h = sigma (1 - (1 + s)^(-1/2)),  s = log2(1 + 2^nu),
// s a smooth positive version of nu (s ~ nu once nu > 3, s -> 0 far away,
// no crease where nu crosses 0). The outer map is bounded: the divergence at
// the boundary becomes an approach to a finite height (nu = 3 -> 0.5 sigma,
// 15 -> 0.75, 99 -> 0.9), so there are no spikes, and since the potential G
// is continuous and 0 on the set, the set's own height is the limit of its
// surroundings: inside (no escape within `iterations` steps) is the plateau
// at the height of nu = iterations, and nu is capped there outside too.
// What is left of a wall at the boundary is the escape time rising faster
// than the samples can follow (taken as is, that is the set's detail); k x k
// points averaged per sample smooth it, and fewer iterations lower it (the
// plateau then takes in the band that escapes late). A logarithm instead of
// the bounded map keeps more relief near the set but leaves a wall of about
// half the terrain's height there. Both maps are monotone, so the level
// curves of the terrain are the equipotentials: mandelbrot_height maps an
// escape time to the height whose contour is its level curve.
//
// The plane: the terrain's width spans 4 / zoom along the real axis, centred
// on (center_x, center_y); sample (i, j) of the whole terrain is
//   c = (center_x + (i - (W - 1) / 2) * step,  center_y - (j - (H - 1) / 2) * step),
//   step = 4 / (zoom (W - 1)),
// so row 0 is the top of the picture (largest imaginary part). Every sample
// is computed from its own global index alone: a window is bit-identical to
// the same samples of the whole, on any thread count.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "core/progress.hpp"

namespace ft::terrain {

inline constexpr int32_t kMaxMandelbrotIterations = 1 << 24;
inline constexpr double kMandelbrotCenterLimit = 4.0;  // |center_x|, |center_y| <= 4
inline constexpr double kMandelbrotMinZoom = 1e-3;     // the width spans at most 4000
// Samples must lie at least this many units in the last place (of the
// largest coordinate in the window, or of 2, the radius inside which every
// iterate lives) apart; below that the grid of c values is visibly uneven.
inline constexpr double kMandelbrotMinUlps = 64.0;
inline constexpr int32_t kMaxMandelbrotSupersample = 8;

struct MandelbrotConfig {
  int32_t width = 513, height = 513;  // samples of the whole terrain
  double center_x = -0.5, center_y = 0.0;
  double zoom = 1.0;                  // the width spans 4 / zoom
  int32_t iterations = 64;            // maximum steps; a point that has not escaped is inside
  double sigma = 1.0;                 // vertical scale of the height map
  int32_t supersample = 2;            // k x k points averaged per sample
  int threads = 0;
  Progress progress;
};

// The iteration of one point, without shortcuts. `count` is the seed's
// integer escape time: the first n >= 1 with |z_n| > 2, or `iterations` when
// the point has not escaped by then (inside). `smooth` is nu(c) above (0
// when inside).
struct EscapeTime {
  int32_t count = 0;
  double smooth = 0.0;
  bool inside = false;
};
EscapeTime escape_time(double cx, double cy, int32_t iterations);

// The terrain height of an escape time nu (see above): sigma (1 - (1 + s)^-1/2).
double mandelbrot_height(double nu, double sigma);

// Distance in the plane between neighbouring samples: 4 / (zoom (width - 1)).
double mandelbrot_spacing(int32_t width, double zoom);
// The deepest zoom that keeps kMandelbrotMinUlps between samples for this
// width and centre (where double precision runs out).
double mandelbrot_max_zoom(int32_t width, double center_x, double center_y);

// Throws FT_ERR_INVALID_ARGUMENT naming the parameter: centre not finite or
// outside [-4, 4], zoom not finite or < 1e-3, iterations outside 1..2^24, or
// a zoom beyond mandelbrot_max_zoom (the message gives the limit).
void validate_mandelbrot(const MandelbrotConfig& c, int64_t max_side = 65536);

// The whole terrain, or the window of w x h samples whose top-left sample
// is (x0, y0) of the whole (any integers: the plane goes on beyond the
// whole's edges). Callers validate.
Heightfield mandelbrot(const MandelbrotConfig& c);
Heightfield mandelbrot_window(const MandelbrotConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h);

}  // namespace ft::terrain
