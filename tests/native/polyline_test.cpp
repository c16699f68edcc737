// SPDX-License-Identifier: GPL-3.0-or-later
// The polyline layer: Nikulin's FPL (seed 003) against the paper's ensemble
// statistics, its structural promises (vertex counts, surviving nodes, delta
// stopping, position-keyed determinism), the variants (3D, dragon,
// lightning), the classic curves, IFS, the measures, validation and the CLI.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analysis/box_counting.hpp"
#include "analysis/polyline_report.hpp"
#include "analysis/polyline_stats.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "golden.hpp"
#include "io/atomic_file.hpp"
#include "io/polyline_io.hpp"
#include "polyline/fpl_study.hpp"
#include "polyline/polyline.hpp"

namespace ft {
namespace {

ft_polyline_params fpl(double spread, int depth, uint64_t seed = 1) {
  ft_polyline_params p = polyline::default_polyline_params();
  p.spread = spread;
  p.depth = depth;
  p.seed = seed;
  return p;
}

ft_status status_of(const ft_polyline_params& p) {
  try {
    polyline::generate_polylines(p);
    return FT_OK;
  } catch (const Error& e) {
    return e.status();
  }
}

double seg_len(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// ---------------------------------------------------------------- statistics

struct Ensemble {
  polyline::MeanSe eta, chi, gamma, mass;
};

Ensemble ensemble(polyline::FplRng rng, double s, int r, int count) {
  polyline::FplStudyConfig c;
  c.rng = rng;
  c.spreads = {s};
  c.depths = {r};
  c.count = count;
  c.seed = 1000;
  c.box_counting = false;
  const polyline::FplStudyRow row = polyline::run_fpl_study(c).front();
  return {row.eta, row.chi, row.gamma, row.mass_dimension};
}

// Tolerances = 3 ensemble standard errors (K = 200 lines; measured per-line
// spreads give se(eta/s) ~ 0.016, se(chi/s) ~ 0.010, se(gamma) <= 0.008)
// plus the error of the paper's fit itself:
//  - eta ~ 0.65 s and chi ~ 0.29 s are two-digit straight-line fits over
//    s = 0..0.5; our means of eta/s drift from 0.650 (s = 0.05) to 0.672
//    (s = 0.4) and chi/s from 0.2944 to 0.2969, so the fits carry +-0.02 and
//    +-0.007 (rounding 0.005 plus that curvature);
//  - gamma ~ 2^(0.71 s^1.82 r) is the two-parameter fit (3), which the
//    paper's fig. 4a shows as close but not exact: 1% of gamma.
TEST(FplStatistics, UniformMatchesPaperFitsAtDepth8) {
  for (double s : {0.1, 0.2, 0.3}) {
    const Ensemble e = ensemble(polyline::FplRng::kUniform, s, 8, 200);
    const double paper_gamma = std::exp2(0.71 * std::pow(s, 1.82) * 8);
    EXPECT_NEAR(e.eta.mean / s, 0.65, 3 * e.eta.se / s + 0.02) << "s = " << s;
    EXPECT_NEAR(e.chi.mean / s, 0.29, 3 * e.chi.se / s + 0.007) << "s = " << s;
    EXPECT_NEAR(e.gamma.mean, paper_gamma, 3 * e.gamma.se + 0.01 * paper_gamma) << "s = " << s;
  }
}

// chi ~ 0.5 sigma for the normal generator; per-line spread gives
// se(chi/sigma) ~ 0.021 at K = 200; the fit carries +-0.01 (rounding 0.005
// plus a drift of our means from 0.506 to 0.510 over sigma = 0.05..0.3).
TEST(FplStatistics, NormalMeanDeviationIsHalfSigma) {
  for (double sigma : {0.1, 0.2}) {
    const Ensemble e = ensemble(polyline::FplRng::kNormal, sigma, 8, 200);
    EXPECT_NEAR(e.chi.mean / sigma, 0.5, 3 * e.chi.se / sigma + 0.01) << "sigma = " << sigma;
  }
}

// Eq. 6: D_r(s) = 1 / (1 - 0.71 s^1.82) against the mean mass dimension.
// Eq. 6 inherits the fit (3), whose exponent alpha s^beta misses our
// log2(gamma) / r by up to 11% at s = 0.1 (2% at 0.2 and 0.3): the
// tolerance is 15% of D6 - 1 plus 3 standard errors.
TEST(FplStatistics, MassDimensionFollowsEquation6) {
  for (double s : {0.1, 0.2, 0.3}) {
    const Ensemble e = ensemble(polyline::FplRng::kUniform, s, 8, 200);
    const double d6 = 1.0 / (1.0 - 0.71 * std::pow(s, 1.82));
    EXPECT_NEAR(e.mass.mean, d6, 3 * e.mass.se + 0.15 * (d6 - 1)) << "s = " << s;
  }
}

// ------------------------------------------------------------------ structure

TEST(Fpl, VertexCountIsTwoToTheDepthPlusOnePerSegment) {
  std::vector<double> base = {0, 0, 0, 1, 0, 0, 1, 1, 0};
  ft_polyline_params p = fpl(0.2, 6);
  p.base = base.data();
  p.base_count = 3;
  const PolylineSet s = polyline::generate_polylines(p);
  EXPECT_EQ(s.line_count(), 1);
  EXPECT_EQ(s.vertex_count(), 2 * 64 + 1);
  EXPECT_EQ(s.radii.size(), s.points.size());
}

TEST(Fpl, BaseNodesSurviveExactly) {
  std::vector<double> base = {0.1, 0.2, 0.3, 1.7, -0.4, 0.0, 2.5, 3.25, 1.0, -1.0, 2.0, 0.5};
  ft_polyline_params p = fpl(0.3, 7, 42);
  p.base = base.data();
  p.base_count = 4;
  const PolylineSet s = polyline::generate_polylines(p);
  for (int i = 0; i < 4; ++i) {
    const Vec3& v = s.points[size_t(i * 128)];
    EXPECT_EQ(v, (Vec3{base[3 * i], base[3 * i + 1], base[3 * i + 2]})) << "node " << i;
  }
}

TEST(Fpl, ZeroSpreadGivesTheStraightSubdivision) {
  const PolylineSet s = polyline::generate_polylines(fpl(0.0, 5));
  for (int i = 0; i <= 32; ++i) {
    EXPECT_DOUBLE_EQ(s.points[size_t(i)][0], i / 32.0);
    EXPECT_EQ(s.points[size_t(i)][1], 0.0);
  }
}

TEST(Fpl, MinLengthStopsSplittingShortSegments) {
  // s = 0: lengths 1, 1/2, 1/4; 1/4 < 0.3 stops: 4 segments despite r = 8.
  ft_polyline_params p = fpl(0.0, 8);
  p.min_length = 0.3;
  EXPECT_EQ(polyline::generate_polylines(p).vertex_count(), 5);
  // With displacements every final segment is < delta or at full depth, and
  // each was split from one >= delta.
  p = fpl(0.3, 12, 9);
  p.min_length = 0.01;
  const PolylineSet s = polyline::generate_polylines(p);
  EXPECT_LT(s.vertex_count(), 4097);
  for (size_t i = 1; i < s.points.size(); ++i) EXPECT_LT(seg_len(s.points[i - 1], s.points[i]), 0.01);
}

TEST(Fpl, DepthFirstAndBreadthFirstPathsAgreeBitForBit) {
  // min_length > 0 takes the printed recursion; a delta below every segment
  // must reproduce the breadth-first fill exactly (draws keyed by position).
  for (int rng : {FT_POLYLINE_RNG_UNIFORM, FT_POLYLINE_RNG_NORMAL})
    for (int method : {FT_POLYLINE_FPL, FT_POLYLINE_FPL3D}) {
      ft_polyline_params p = fpl(0.25, 14, 5);  // 14 > 12: the blocked path too
      p.rng = rng;
      p.method = method;
      const PolylineSet a = polyline::generate_polylines(p);
      p.min_length = 1e-300;
      const PolylineSet b = polyline::generate_polylines(p);
      ASSERT_EQ(a.points.size(), b.points.size());
      EXPECT_TRUE(a.points == b.points) << "rng " << rng << " method " << method;
    }
}

TEST(Fpl, SameSeedSameBitsOtherSeedOtherLine) {
  const PolylineSet a = polyline::generate_polylines(fpl(0.2, 10, 77));
  const PolylineSet b = polyline::generate_polylines(fpl(0.2, 10, 77));
  const PolylineSet c = polyline::generate_polylines(fpl(0.2, 10, 78));
  EXPECT_TRUE(a.points == b.points);
  EXPECT_FALSE(a.points == c.points);
}

TEST(Fpl, GoldenChecksumsPinTheOutput) {
  // Points, radii and line offsets of the FPL generators and the profile method (see golden.hpp).
  struct Case {
    int method, rng;
    double branch_prob;
    uint64_t want;
  };
  const Case cases[] = {{FT_POLYLINE_FPL, FT_POLYLINE_RNG_UNIFORM, 0.0, 0x328482491f34dd36ULL},
                        {FT_POLYLINE_FPL, FT_POLYLINE_RNG_NORMAL, 0.0, 0x2e0723d9703586dfULL},
                        {FT_POLYLINE_FPL3D, FT_POLYLINE_RNG_NORMAL, 0.3, 0x1cb25f23c99d3f10ULL},
                        {FT_POLYLINE_PROFILE, FT_POLYLINE_RNG_UNIFORM, 0.0, 0xc604ca3107a79f18ULL}};
  for (const Case& c : cases) {
    ft_polyline_params p = fpl(0.2, 10, 2024);
    p.method = c.method, p.rng = c.rng, p.branch_prob = c.branch_prob;
    const PolylineSet s = polyline::generate_polylines(p);
    uint64_t got = test::fnv1a(s.points.data(), s.points.size() * sizeof(Vec3));
    got = test::fnv1a(s.radii.data(), s.radii.size() * sizeof(double), got);
    got = test::fnv1a(s.offsets.data(), s.offsets.size() * sizeof(int64_t), got);
    std::printf("method %d rng %d branch %g: 0x%016llxULL\n", c.method, c.rng, c.branch_prob,
                (unsigned long long)got);
    EXPECT_EQ(got, c.want) << "method " << c.method << " rng " << c.rng;
  }
}

TEST(Fpl, OutputDoesNotDependOnTheThreadCount) {
  ft_polyline_params p = fpl(0.3, 16, 11);  // 16 blocks of 2^12 vertices
  for (int method : {FT_POLYLINE_FPL, FT_POLYLINE_FPL3D}) {
    p.method = method;
    p.threads = 1;
    const PolylineSet one = polyline::generate_polylines(p);
    p.threads = 3;
    const PolylineSet three = polyline::generate_polylines(p);
    EXPECT_TRUE(one.points == three.points) << "method " << method;
  }
}

TEST(Fpl, ThreeDimensionalDisplacementIsPerpendicular) {
  ft_polyline_params p = fpl(0.3, 1, 3);
  p.method = FT_POLYLINE_FPL3D;
  std::vector<double> base = {0, 0, 0, 1, 2, 3};
  p.base = base.data();
  p.base_count = 2;
  const PolylineSet s = polyline::generate_polylines(p);
  ASSERT_EQ(s.vertex_count(), 3);
  const Vec3 v{1, 2, 3}, d{s.points[1][0] - 0.5, s.points[1][1] - 1.0, s.points[1][2] - 1.5};
  EXPECT_NEAR(v[0] * d[0] + v[1] * d[1] + v[2] * d[2], 0.0, 1e-12);
  EXPECT_LE(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), 0.3 * std::sqrt(14.0) + 1e-12);
  // In a plane with normal z the 3D rule is the 2D rule.
  p = fpl(0.2, 9, 4);
  const PolylineSet flat = polyline::generate_polylines(p);
  p.method = FT_POLYLINE_FPL3D;
  p.plane_normal[2] = 1;
  const PolylineSet planar = polyline::generate_polylines(p);
  for (size_t i = 0; i < flat.points.size(); ++i)
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(flat.points[i][size_t(k)], planar.points[i][size_t(k)], 1e-12);
}

TEST(Fpl, DragonHasEqualSegmentsAtRightAngles) {
  ft_polyline_params p = fpl(0.0, 10);
  p.method = FT_POLYLINE_DRAGON;
  const PolylineSet s = polyline::generate_polylines(p);
  ASSERT_EQ(s.vertex_count(), 1025);
  const double len = std::exp2(-5.0);  // (1/sqrt 2)^10
  for (size_t i = 1; i < s.points.size(); ++i) ASSERT_NEAR(seg_len(s.points[i - 1], s.points[i]), len, 1e-12);
  EXPECT_EQ(s.points.back(), (Vec3{1, 0, 0}));
  // First fold to the left: the level-0 midpoint is at (0.5, 0.5).
  EXPECT_NEAR(s.points[512][0], 0.5, 1e-15);
  EXPECT_NEAR(s.points[512][1], 0.5, 1e-15);
}

TEST(Lightning, BranchesForkFromTheLineAndTaper) {
  ft_polyline_params p = fpl(0.1, 10, 7);
  p.branch_prob = 0.5;
  p.radius = 0.01;
  const PolylineSet s = polyline::generate_polylines(p);
  ASSERT_GT(s.line_count(), 1);
  const PolylineSet again = polyline::generate_polylines(p);
  EXPECT_TRUE(s.points == again.points);
  EXPECT_TRUE(s.offsets == again.offsets);
  // Each branch starts exactly on a vertex of an earlier line, thinner.
  for (int64_t l = 1; l < s.line_count(); ++l) {
    const Vec3& start = s.points[size_t(s.line_begin(l))];
    bool found = false;
    for (int64_t v = 0; v < s.line_begin(l) && !found; ++v) found = s.points[size_t(v)] == start;
    EXPECT_TRUE(found) << "branch " << l;
    EXPECT_LE(s.radii[size_t(s.line_begin(l))], 0.5 * 0.01 + 1e-15);
    EXPECT_LT(s.radii[size_t(s.line_end(l) - 1)], s.radii[size_t(s.line_begin(l))]);
  }
  // The main line still goes through its nodes.
  EXPECT_EQ(s.points[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(s.points[1024], (Vec3{1, 0, 0}));
}

// ------------------------------------------------------------ classic curves

TEST(ClassicCurves, KochAndArrowheadHaveTheirCountsLengthsAndEnds) {
  ft_polyline_params p = fpl(0, 5);
  p.method = FT_POLYLINE_KOCH;
  PolylineSet k = polyline::generate_polylines(p);
  EXPECT_EQ(k.vertex_count(), 1025);
  EXPECT_NEAR(analysis::line_stats(k, 0).gamma, std::pow(4.0 / 3.0, 5), 1e-9);
  EXPECT_EQ(k.points.back(), (Vec3{1, 0, 0}));
  p.method = FT_POLYLINE_SIERPINSKI;
  for (int d : {4, 5}) {
    p.depth = d;
    PolylineSet a = polyline::generate_polylines(p);
    EXPECT_EQ(a.vertex_count(), int64_t(std::pow(3, d)) + 1);
    EXPECT_NEAR(analysis::line_stats(a, 0).gamma, std::pow(1.5, d), 1e-9);
    EXPECT_EQ(a.points.back(), (Vec3{1, 0, 0}));
  }
}

TEST(Ifs, BarnsleyFernFillsItsKnownBox) {
  ft_polyline_params p = polyline::default_polyline_params();
  p.method = FT_POLYLINE_IFS;
  p.ifs_points = 20000;
  const PolylineSet s = polyline::generate_polylines(p);
  EXPECT_EQ(s.line_count(), 20000);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Vec3& q : s.points) x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]), y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
  // The fern's attractor spans about x in [-2.18, 2.66], y in [0, 9.99].
  EXPECT_GT(x0, -2.3);
  EXPECT_LT(x1, 2.8);
  EXPECT_GE(y0, 0.0);
  EXPECT_LT(y1, 10.01);
  EXPECT_GT(y1, 9.0);
}

TEST(Ifs, SierpinskiGasketHasBoxDimensionLog3OverLog2) {
  // The gasket of seed 002: three maps of ratio 1/2 towards the corners of
  // the unit equilateral triangle. Its level-k pieces are 3^k triangles of
  // side 2^-k, each of measure 3^-k, so N(2^-k) grows like 3^k and
  // D = log 3 / log 2 = 1.585.
  //
  // Point count and box sizes. In random iteration the point after step n
  // lies in the level-k piece addressed by the last k maps drawn, so each
  // point falls in a given piece with probability exactly 3^-k: with N
  // points a piece stays empty with probability (1 - 3^-k)^N ~ exp(-N/3^k).
  // N = 2^18 = 262144 and the smallest box 2^-7 give 3^7 = 2187 pieces of
  // 120 points each (an empty one: e^-120); a box that holds only a piece
  // two levels down (side 2^-9, a quarter of the box) still expects 13
  // points (missed with probability 2e-6 per box, ~0.01 boxes of ~10^4).
  // The largest box is 1/4: at 1/2 the whole gasket lies in 3 or 4 boxes,
  // its outline rather than its structure. Six octaves from 1/4 to 1/128 at
  // two sizes per octave is a whole number of periods of the count's
  // log-periodic ripple (the gasket repeats at ratio 2), which the fit then
  // averages out; the 4 grid shifts take the smallest count, as for the
  // Koch curve and the arrowhead above. The tolerance is the 0.05.
  // Measured: 1.614 (fit standard error 0.004), 0.029 above log 3 / log 2.
  // The excess is deterministic, not noise: square boxes along the
  // triangle's sides and holes add counts of lower order than 3^k whose share
  // shrinks like (2/3)^k, so a fit over finer sizes comes closer (1.606 from
  // 1/8 to 1/256 with 2^20 points, at 5 times the run time).
  ft_polyline_params p = polyline::default_polyline_params();
  p.method = FT_POLYLINE_IFS;
  p.ifs_preset = FT_IFS_SIERPINSKI_GASKET;
  p.ifs_points = 1 << 18;
  p.seed = 3;
  const PolylineSet s = polyline::generate_polylines(p);
  ASSERT_EQ(s.line_count(), 1 << 18);
  const double h = std::sqrt(3.0) / 2;
  for (const Vec3& q : s.points) {
    // Inside the triangle (0, 0), (1, 0), (1/2, h), up to rounding.
    ASSERT_GE(q[1], -1e-12);
    ASSERT_LE(q[1], h * (1 - std::fabs(2 * q[0] - 1)) + 1e-12) << q[0] << " " << q[1];
  }
  analysis::BoxCountOptions o;
  o.max_size = 0.25;
  o.min_size = 1.0 / 128;
  const analysis::BoxCountResult r = analysis::box_counting_dimension(s, o);
  EXPECT_NEAR(r.dimension, std::log(3.0) / std::log(2.0), 0.05) << "stderr " << r.std_error;
}

TEST(Ifs, UserTableIsUsedAndBadTablesAreRejected) {
  // Two halvings toward 0 and 1 on the x axis: the attractor is [0, 1].
  std::vector<double> t = {0.5, 0, 0, 0.5, 0, 0, 1, 0.5, 0, 0, 0.5, 0.5, 0, 1};
  ft_polyline_params p = polyline::default_polyline_params();
  p.method = FT_POLYLINE_IFS;
  p.ifs_table = t.data();
  p.ifs_maps = 2;
  p.ifs_points = 5000;
  const PolylineSet s = polyline::generate_polylines(p);
  for (const Vec3& q : s.points) ASSERT_TRUE(q[0] >= 0 && q[0] <= 1 && q[1] == 0);
  t[6] = -1;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  t[6] = 1, t[0] = NAN;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  t[0] = 3;  // expanding: the orbit diverges
  p.ifs_points = 100000;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
}

TEST(Profile, VossProfileKeepsItsNodes) {
  std::vector<double> base = {0, 0, 0, 2, 1, 0, 4, 0, 0};
  ft_polyline_params p = fpl(0.1, 7);
  p.method = FT_POLYLINE_PROFILE;
  p.base = base.data();
  p.base_count = 3;
  const PolylineSet s = polyline::generate_polylines(p);
  EXPECT_EQ(s.vertex_count(), 2 * 128 + 1);
  EXPECT_EQ(s.points[128], (Vec3{2, 1, 0}));
  EXPECT_EQ(s.points.back(), (Vec3{4, 0, 0}));
}

// ------------------------------------------------------------------- measures

TEST(PolylineStats, MatchEquationOneOnAKnownLine) {
  PolylineSet s;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{0.5, 0.5, 0}, Vec3{1, 0, 0}}) s.add(v);
  s.end_line();
  const analysis::LineStats st = analysis::line_stats(s, 0);
  EXPECT_DOUBLE_EQ(st.eta, 0.5);
  EXPECT_DOUBLE_EQ(st.chi, 0.5 / 3);
  EXPECT_DOUBLE_EQ(st.gamma, std::sqrt(2.0));
  // M_r / M_{r-1} = sqrt 2: D = 1 / (1 - 1/2) = 2, the dragon's value.
  EXPECT_DOUBLE_EQ(analysis::mass_dimension(s, 0), 2.0);
  // Scale-free: the same shape on a chord of 10 gives the same numbers.
  PolylineSet big;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{5, 5, 0}, Vec3{10, 0, 0}}) big.add(v);
  big.end_line();
  EXPECT_DOUBLE_EQ(analysis::line_stats(big, 0).eta, 0.5);
}

TEST(PolylineStats, ReportHasEveryMeasure) {
  const nlohmann::json j = analysis::polyline_report(polyline::generate_polylines(fpl(0.2, 10)));
  for (const char* k : {"lines", "vertices", "length", "eta", "chi", "gamma", "mass_dimension", "box_counting"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_GT(j["box_counting"]["dimension"].get<double>(), 1.0);
  EXPECT_LT(j["box_counting"]["dimension"].get<double>(), 1.2);
  // A two-vertex line cannot be box-counted automatically: an error entry.
  PolylineSet two;
  two.add({0, 0, 0});
  two.add({1, 0, 0});
  two.end_line();
  EXPECT_TRUE(analysis::polyline_report(two)["box_counting"].contains("error"));
}

// ----------------------------------------------------------------- validation

TEST(PolylineValidation, RejectsBadInputWithClearErrors) {
  std::vector<double> one = {0, 0, 0};
  ft_polyline_params p = fpl(0.1, 4);
  p.base = one.data();
  p.base_count = 1;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  std::vector<double> nan = {0, 0, 0, NAN, 1, 0};
  p.base = nan.data();
  p.base_count = 2;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  std::vector<double> same = {0, 0, 0, 1, 1, 0, 1, 1, 0};
  p.base = same.data();
  p.base_count = 3;
  try {
    polyline::generate_polylines(p);
    ADD_FAILURE() << "coincident nodes accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("coincides"), std::string::npos) << e.what();
  }
  p = fpl(-0.1, 4);
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(NAN, 4);
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, -1);
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, 35);
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, 4);
  p.method = 99;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, 4);
  p.branch_prob = 1.5;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, 4);
  p.min_length = -1;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, 4);
  p.struct_size = 8;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
  p = fpl(0.1, 4);
  p.method = FT_POLYLINE_FPL3D;
  p.plane_normal[0] = 1;  // parallel to the unit segment
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
}

TEST(PolylineValidation, DepthBeyondMemoryIsTooLargeBeforeAllocating) {
  // 2^34 vertices x 32 bytes = 512 GiB: refused against any cap.
  EXPECT_EQ(status_of(fpl(0.1, 34)), FT_ERR_TOO_LARGE);
  // With delta > 0 the counting pass stops at the cap instead of running on.
  set_memory_cap(uint64_t(1) << 20);
  ft_polyline_params p = fpl(0.1, 30);
  p.min_length = 1e-12;
  EXPECT_EQ(status_of(p), FT_ERR_TOO_LARGE);
  set_memory_cap(0);
}

// ------------------------------------------------------------------------ CLI

int run_cli(const std::string& args) {
  return std::system((std::string(FT_CLI_PATH) + " " + args + " >/dev/null 2>&1").c_str());
}

TEST(PolylineCli, WritesCsvThatReadsBackAndStudyWritesCsvAndSvg) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_polyline_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string csv = (dir / "l.csv").string();
  ASSERT_EQ(run_cli("polyline --method fpl --base \"0,0;1,0;1,1\" --spread 0.2 --depth 6 --seed 3 --out " + csv), 0);
  const PolylineSet s = io::read_polylines(csv);
  EXPECT_EQ(s.vertex_count(), 129);
  EXPECT_EQ(s.points[64], (Vec3{1, 0, 0}));
  EXPECT_NE(run_cli("polyline --base \"0,0\" --out " + csv), 0);
  EXPECT_NE(run_cli("polyline --spread -1 --out " + csv), 0);
  const std::string table = (dir / "s.csv").string(), svg = (dir / "s.svg").string();
  ASSERT_EQ(run_cli("study fpl --spread 0.1,0.2 --depth 4,6 --count 10 --no-box --out-csv " + table + " --plot " + svg), 0);
  const std::string text = io::read_file(table);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 5);  // header + 4 rows
  EXPECT_NE(io::read_file(svg).find("</svg>"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ft
