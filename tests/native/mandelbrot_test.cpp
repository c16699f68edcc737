// SPDX-License-Identifier: GPL-3.0-or-later
// The Mandelbrot terrain (seed 002): escape counts against hand iteration,
// the continuity of the smooth count, windows, threads, the height map and
// its level curves, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "contour/marching_squares.hpp"
#include "core/error.hpp"
#include "terrain/mandelbrot.hpp"
#include "terrain/terrain.hpp"

namespace ft {
namespace {

ft_terrain_params mandelbrot_params(int32_t w, int32_t h, double cx, double cy, double zoom, int32_t iterations,
                                    int32_t supersample = 1) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = FT_TERRAIN_MANDELBROT;
  p.width = w, p.height = h, p.center_x = cx, p.center_y = cy, p.zoom = zoom, p.iterations = iterations;
  p.supersample = supersample;
  return p;
}

// The height of one point of the plane as the terrain defines it.
double point_height(double cx, double cy, const ft_terrain_params& p) {
  const terrain::EscapeTime e = terrain::escape_time(cx, cy, p.iterations);
  return terrain::mandelbrot_height(e.inside ? p.iterations : std::min(e.smooth, double(p.iterations)), p.sigma);
}

bool same_bits(const Heightfield& a, const Heightfield& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

std::string error_of(const ft_terrain_params& p) {
  try {
    terrain::validate_terrain_params(p);
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_INVALID_ARGUMENT);
    return e.what();
  }
  return "";
}

TEST(Mandelbrot, PointsInsideTheSetReachTheMaximum) {
  // 0 is the fixed point of z^2; -1 the 2-cycle 0, -1, 0, -1; i the
  // pre-periodic orbit i, -1 + i, -i, -1 + i, ...; -2 the orbit -2, 2, 2, 2
  // that sits on the escape circle (|z| = 2 is not > 2) for ever.
  for (const auto& c : {std::pair{0.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {-2.0, 0.0}}) {
    const terrain::EscapeTime e = terrain::escape_time(c.first, c.second, 1000);
    EXPECT_TRUE(e.inside) << c.first << " " << c.second;
    EXPECT_EQ(e.count, 1000);
  }
}

TEST(Mandelbrot, PointsOutsideEscapeAtTheHandComputedCount) {
  // The seed's count: the first n with |z_n| > 2, z_0 = 0. By hand (exact
  // for these c): c = 1: 1, 2, 5 -> 3. c = 2: 2, 6 -> 2. c = 1/2: .5, .75,
  // 1.0625, 1.6289, 3.1533 -> 5. c = -5/2: -2.5 -> 1. c = 1.5i: 1.5i,
  // -2.25 + 1.5i -> 2. c = -1.5 + 0.5i: -1.5 + .5i, .5 - i, -2.25 - .5i -> 3.
  // c = 3/10 creeps past the parabolic point 1/4 and leaves at step 12
  // (exact rational iteration).
  const struct {
    double x, y;
    int32_t n;
  } cases[] = {{1, 0, 3}, {2, 0, 2}, {0.5, 0, 5}, {-2.5, 0, 1}, {0, 1.5, 2}, {-1.5, 0.5, 3}, {0.3, 0, 12}};
  for (const auto& c : cases) {
    const terrain::EscapeTime e = terrain::escape_time(c.x, c.y, 1000);
    EXPECT_FALSE(e.inside);
    EXPECT_EQ(e.count, c.n) << c.x << " " << c.y;
    // The smooth count nu stays within one step below the integer count:
    // nu = k on the equipotential through the lemniscate |z_k| = 2 in the
    // limit of large |z|, and the band {count = n} lies between the
    // lemniscates n - 1 and n.
    EXPECT_GT(e.smooth, c.n - 1.5) << c.x;
    EXPECT_LT(e.smooth, c.n + 0.5) << c.x;
  }
  // With fewer iterations than it needs, a point that escapes late is inside.
  EXPECT_TRUE(terrain::escape_time(0.3, 0, 11).inside);
  EXPECT_FALSE(terrain::escape_time(0.3, 0, 12).inside);
}

TEST(Mandelbrot, SmoothCountHasNoStepsWhereTheIntegerCountJumps) {
  // Along the real axis from 0.4 to 2 the integer count falls from 8 to 2 in
  // steps of 1. nu is continuous and its slope there is below 20 per unit
  // (it is largest near 0.4, a fifth of the way from the parabolic point
  // 1/4), so neighbours 1.6e-4 apart differ by < 0.01; a count read at
  // radius 2 instead of 2^16 jumps by up to 0.4 at every step of n.
  const int n = 10001;
  double worst = 0;
  int jumps = 0;
  terrain::EscapeTime prev = terrain::escape_time(0.4, 0, 1000);
  for (int k = 1; k < n; ++k) {
    const double x = 0.4 + 1.6 * k / (n - 1);
    const terrain::EscapeTime e = terrain::escape_time(x, 0, 1000);
    worst = std::max(worst, std::fabs(e.smooth - prev.smooth));
    jumps += e.count != prev.count;
    prev = e;
  }
  EXPECT_GE(jumps, 5);
  EXPECT_LT(worst, 0.01);
}

TEST(Mandelbrot, EverySampleIsTheIterationOfItsPoint) {
  // Sample (i, j) is c = centre + ((i - (W-1)/2) step, -(j - (H-1)/2) step)
  // (row 0 at the top), its height the height map of its escape time capped
  // at `iterations`, the plateau at that cap inside; the cardioid and bulb
  // shortcut changes nothing.
  const ft_terrain_params p = mandelbrot_params(97, 65, -0.6, 0.1, 1.3, 200);
  const Heightfield hf = terrain::generate_terrain(p);
  const double step = 4.0 / (p.zoom * 96);
  const float top = float(terrain::mandelbrot_height(200, p.sigma));
  int inside = 0;
  for (int32_t j = 0; j < 65; ++j)
    for (int32_t i = 0; i < 97; ++i) {
      const double cx = p.center_x + (i - 48.0) * step, cy = p.center_y - (j - 32.0) * step;
      inside += terrain::escape_time(cx, cy, p.iterations).inside;
      ASSERT_EQ(hf.at(i, j), float(point_height(cx, cy, p))) << i << " " << j;
      ASSERT_LE(hf.at(i, j), top);
    }
  EXPECT_GT(inside, 300);  // the view holds the cardioid and the bulb
  EXPECT_EQ(hf.stats().max, top);
  EXPECT_EQ(hf.world_size(), p.world_size);
}

TEST(Mandelbrot, SupersamplingAveragesAKByKSplitOfEachSample) {
  // k = 3: the points at offsets -1/3, 0, 1/3 of a sample spacing, summed
  // row by row and divided by 9.
  const ft_terrain_params p = mandelbrot_params(41, 31, -0.75, 0.1, 6.0, 300, 3);
  const Heightfield hf = terrain::generate_terrain(p);
  const double step = 4.0 / (p.zoom * 40);
  for (int32_t j = 0; j < 31; j += 3)
    for (int32_t i = 0; i < 41; i += 2) {
      double sum = 0;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a)
          sum += point_height(p.center_x + (i - 20.0 + ((a + 0.5) / 3 - 0.5)) * step,
                              p.center_y - (j - 15.0 + ((b + 0.5) / 3 - 0.5)) * step, p);
      ASSERT_EQ(hf.at(i, j), float(sum / 9.0)) << i << " " << j;
    }
  ft_terrain_params q = p;
  q.supersample = 0;
  EXPECT_THROW(terrain::validate_terrain_params(q), Error);
  q.supersample = 9;
  EXPECT_THROW(terrain::validate_terrain_params(q), Error);
}

TEST(Mandelbrot, AWindowEqualsTheSameSamplesOfTheWhole) {
  const ft_terrain_params p = mandelbrot_params(301, 203, -0.745, 0.113, 40.0, 500, 2);
  const Heightfield whole = terrain::generate_terrain(p);
  terrain::MandelbrotConfig c;
  c.width = p.width, c.height = p.height, c.center_x = p.center_x, c.center_y = p.center_y;
  c.zoom = p.zoom, c.iterations = p.iterations, c.sigma = p.sigma, c.supersample = p.supersample;
  const struct {
    int64_t x0, y0;
    int32_t w, h;
  } windows[] = {{0, 0, 301, 203}, {17, 5, 64, 33}, {150, 100, 151, 103}, {299, 0, 2, 203}, {3, 190, 97, 13}};
  for (const auto& win : windows) {
    const Heightfield part = terrain::mandelbrot_window(c, win.x0, win.y0, win.w, win.h);
    for (int32_t j = 0; j < win.h; ++j)
      ASSERT_EQ(std::memcmp(part.data() + size_t(j) * size_t(win.w),
                            whole.data() + size_t(win.y0 + j) * 301 + size_t(win.x0), size_t(win.w) * 4),
                0)
          << "window at " << win.x0 << "," << win.y0 << " row " << j;
  }
}

TEST(Mandelbrot, SameBitsOnAnyThreadCount) {
  ft_terrain_params p = mandelbrot_params(257, 129, -0.1, 0.9, 8.0, 400, 2);
  p.threads = 1;
  const Heightfield one = terrain::generate_terrain(p);
  for (int t : {2, 3, 7}) {
    p.threads = t;
    EXPECT_TRUE(same_bits(one, terrain::generate_terrain(p))) << t << " threads";
  }
}

TEST(Mandelbrot, HeightMapIsMonotoneAndBoundedSoTheBoundaryDoesNotSpike) {
  double prev = terrain::mandelbrot_height(-40.0, 1.0);
  EXPECT_GE(prev, 0.0);
  EXPECT_LT(prev, 1e-9);  // far from the set the plain tends to 0
  for (double nu = -39.5; nu <= 1e6; nu = nu < 2000 ? nu + 0.5 : nu * 1.5) {
    const double h = terrain::mandelbrot_height(nu, 1.0);
    ASSERT_GT(h, prev) << nu;
    ASSERT_LT(h, 1.0) << nu;  // bounded by sigma however close to the set
    prev = h;
  }
  // 1 - (1 + s)^-1/2, s = log2(1 + 2^nu): s(0) = 1; s(15) = 15 + 3e-5; s(99) ~ 99.
  EXPECT_NEAR(terrain::mandelbrot_height(0.0, 1.0), 1 - std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(terrain::mandelbrot_height(15.0, 1.0), 0.75, 1e-5);
  EXPECT_NEAR(terrain::mandelbrot_height(99.0, 2.0), 1.8, 1e-12);
}

TEST(Mandelbrot, LevelCurvesAreCurvesOfEqualEscapeTime) {
  // The contour at the height of nu = 3 is the equipotential nu = 3: one
  // closed loop around the whole set, inside the view. Every vertex lies on
  // a grid edge between two samples whose nu straddle 3, so mapping it back
  // to the plane gives nu within the change of nu over one sample spacing
  // (at most ~0.2 for nu = 3 at 0.016 per sample: |grad nu| < 12 there).
  const ft_terrain_params p = mandelbrot_params(257, 257, -0.5, 0.0, 1.0, 256, 1);
  const Heightfield hf = terrain::generate_terrain(p);
  const PolylineSet set = contour::marching_squares(hf, std::vector<double>{terrain::mandelbrot_height(3.0, p.sigma)});
  ASSERT_EQ(set.line_count(), 1);
  EXPECT_EQ(contour::chain_kind(set, 0), contour::ChainKind::kIsland);
  const double step = 4.0 / 256;
  double worst = 0;
  for (const Vec3& v : set.points) {
    const terrain::EscapeTime e = terrain::escape_time(p.center_x + (v[0] - 128) * step, p.center_y - (v[1] - 128) * step, 256);
    worst = std::max(worst, std::fabs(e.smooth - 3.0));
  }
  EXPECT_LT(worst, 0.2);
  // Several levels come out one after another, nested loops.
  const PolylineSet rings =
      contour::marching_squares(hf, std::vector<double>{terrain::mandelbrot_height(2.0, 1.0), terrain::mandelbrot_height(3.0, 1.0)});
  EXPECT_EQ(rings.line_count(), 2);
  EXPECT_GT(std::fabs(contour::signed_area(rings, 0)), std::fabs(contour::signed_area(rings, 1)));
}

TEST(Mandelbrot, RejectsBadParametersWithTheirName) {
  ft_terrain_params p = mandelbrot_params(129, 129, -0.5, 0, 1, 256);
  EXPECT_EQ(error_of(p), "");
  p.zoom = 0;
  EXPECT_NE(error_of(p).find("zoom must be a finite number >= 0.001"), std::string::npos) << error_of(p);
  p.zoom = -2;
  EXPECT_NE(error_of(p).find("zoom"), std::string::npos);
  p.zoom = NAN;
  EXPECT_NE(error_of(p).find("zoom"), std::string::npos);
  p.zoom = INFINITY;
  EXPECT_NE(error_of(p).find("zoom"), std::string::npos);
  p.zoom = 1;
  p.center_x = NAN;
  EXPECT_NE(error_of(p).find("center_x must be in [-4, 4], got NaN"), std::string::npos) << error_of(p);
  p.center_x = -0.5;
  p.center_y = 5;
  EXPECT_NE(error_of(p).find("center_y"), std::string::npos);
  p.center_y = 0;
  p.iterations = 0;
  EXPECT_NE(error_of(p).find("iterations must be in 1..16777216, got 0"), std::string::npos) << error_of(p);
  p.iterations = (1 << 24) + 1;
  EXPECT_NE(error_of(p).find("iterations"), std::string::npos);
  p.iterations = 256;
  p.width = 1;
  EXPECT_NE(error_of(p).find("width"), std::string::npos);
}

TEST(Mandelbrot, RefusesAZoomBeyondDoublePrecisionAndSaysWhere) {
  // Near |c| <= 2 doubles are 2^-51 apart; 64 of them between samples is
  // 2^-45 = 2.8e-14, so 1025 samples across span at least 2.9e-11 and the
  // zoom (4 / span) can reach 4 / (1024 * 2^-45) = 1.37e11.
  ft_terrain_params p = mandelbrot_params(1025, 1025, -0.1, 0.0, 1e11, 64);
  const double limit = terrain::mandelbrot_max_zoom(1025, -0.1, 0.0);
  EXPECT_NEAR(limit, 4.0 / (1024 * std::ldexp(1.0, -45)), 1e-3 * limit);
  p.zoom = 0.99 * limit;
  EXPECT_EQ(error_of(p), "");
  p.zoom = 1.01 * limit;
  const std::string e = error_of(p);
  EXPECT_NE(e.find("beyond double precision"), std::string::npos) << e;
  EXPECT_NE(e.find("can reach 1.37e+11"), std::string::npos) << e;
  // Fewer samples across allow a deeper zoom; the same zoom then works.
  p.width = p.height = 65;
  EXPECT_EQ(error_of(p), "");
  // Deep inside the cardioid the whole window is the set: the plateau, quickly.
  p.zoom = 0.99 * terrain::mandelbrot_max_zoom(65, -0.1, 0.0);
  const Heightfield hf = terrain::generate_terrain(p);
  EXPECT_EQ(hf.stats().min, float(terrain::mandelbrot_height(64, p.sigma)));
  EXPECT_EQ(hf.stats().max, float(terrain::mandelbrot_height(64, p.sigma)));
}

TEST(Mandelbrot, DeepZoomStillResolvesDistinctSamples) {
  // At 0.9 of the precision limit, near a boundary point (the Misiurewicz
  // point -0.1011 + 0.9563i), neighbouring samples are distinct points of
  // the plane and the terrain is not flat: the grid did not collapse.
  const double cx = -0.10109636384562, cy = 0.95628651080914;
  ft_terrain_params p = mandelbrot_params(65, 65, cx, cy, 0.9 * terrain::mandelbrot_max_zoom(65, cx, cy), 2000);
  const Heightfield hf = terrain::generate_terrain(p);
  int distinct = 0;
  for (int32_t i = 1; i < 65; ++i) distinct += hf.at(i, 32) != hf.at(i - 1, 32);
  EXPECT_GT(distinct, 48);
}

TEST(Mandelbrot, ProgressCanCancel) {
  ft_terrain_params p = mandelbrot_params(257, 257, -0.5, 0, 1, 256);
  int calls = 0;
  p.progress = [](void* user, double) -> int { return ++*static_cast<int*>(user) >= 2; };
  p.progress_user = &calls;
  try {
    terrain::generate_terrain(p);
    FAIL() << "not cancelled";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_CANCELLED);
  }
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace ft
