// SPDX-License-Identifier: GPL-3.0-or-later
// Terrain layer: Voss midpoint displacement (1D, 2D), Feder's additions,
// reference points, periodic terrains, determinism, bad input.
//
// The scaling law is checked with an estimator written here, independently of
// the library's analysis layer: the variance of increments over lag tau,
// using only pairs of points aligned to the grid on which that lag was made
// (the exact statement of the midpoint method), fitted in log-log.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "golden.hpp"
#include "terrain/midpoint_steps.hpp"
#include "terrain/terrain.hpp"

namespace ft {
namespace {

ft_terrain_params terrain(int method, int levels, double hurst, uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = method;
  p.levels = levels;
  p.hurst = hurst;
  p.seed = seed;
  return p;
}

// Least-squares slope of y on x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxy / sxx;
}

using test::checksum;  // golden checksums of bit-exact output (golden.hpp)

// H from an ensemble of 2D terrains: for each lag D = 2^j, the mean squared
// increment along rows and columns between neighbouring points of the grid
// of spacing D (both points on that level's grid), over lags jmin..jmax.
double aligned_hurst_2d(int method, int levels, double hurst, int count, int jmin, int jmax) {
  std::vector<double> logd, logv;
  std::vector<double> sum(size_t(jmax) + 1, 0.0), num(size_t(jmax) + 1, 0.0);
  for (int k = 0; k < count; ++k) {
    ft_terrain_params p = terrain(method, levels, hurst, 1000 + k);
    p.threads = 1;
    const Heightfield hf = terrain::generate_terrain(p);
    const int n = hf.width() - 1;
    for (int j = jmin; j <= jmax; ++j) {
      const int d = 1 << j;
      for (int y = 0; y <= n; y += d)
        for (int x = 0; x + d <= n; x += d) {
          const double a = hf.at(x + d, y) - hf.at(x, y);
          const double b = hf.at(y, x + d) - hf.at(y, x);  // the transposed pair: columns
          sum[size_t(j)] += a * a + b * b;
          num[size_t(j)] += 2;
        }
    }
  }
  for (int j = jmin; j <= jmax; ++j) {
    logd.push_back(j * std::log(2.0));
    logv.push_back(std::log(sum[size_t(j)] / num[size_t(j)]));
  }
  return slope(logd, logv) / 2.0;
}

// ---------------------------------------------------------------- scaling law

class ProfileScaling : public ::testing::TestWithParam<double> {};

TEST_P(ProfileScaling, AlignedIncrementVarianceGrowsAsLagToTheTwoH) {
  // Voss 1D with rho = sqrt(1 - 2^(2H-2)) makes Var[X(t + tau) - X(t)] =
  // sigma^2 tau^(2H) exactly for grid-aligned pairs. Ensemble: 300 profiles of
  // 2^12 + 1 samples, lags 2^-12 .. 2^-3. The coarsest lag used has 8 pairs a
  // profile, 2400 in all: the relative standard error of its variance is
  // sqrt(2 / 2400) = 2.9%, i.e. 0.029 in log; spread over the 9 octaves of
  // the fit that moves the slope by < 0.01 and H by < 0.005. Tolerance 0.05
  // (the issue's) leaves room for nothing but a wrong rho or scale schedule.
  const double H = GetParam();
  const int levels = 12, count = 300;
  std::vector<double> sum(levels + 1, 0.0), num(levels + 1, 0.0);
  std::vector<float> x((1 << levels) + 1);
  for (int k = 0; k < count; ++k) {
    ft_profile_params p = terrain::default_profile_params();
    p.levels = levels;
    p.hurst = H;
    p.seed = 77 + k;
    terrain::generate_profile(p, x.data(), x.size());
    for (int j = 0; j <= levels; ++j) {
      const int d = 1 << j;
      for (int i = 0; i + d <= (1 << levels); i += d) {
        const double inc = x[size_t(i + d)] - x[size_t(i)];
        sum[size_t(j)] += inc * inc;
        num[size_t(j)] += 1;
      }
    }
  }
  std::vector<double> logt, logv;
  for (int j = 0; j <= levels - 3; ++j) {
    logt.push_back((j - levels) * std::log(2.0));  // tau = 2^j / 2^levels
    logv.push_back(std::log(sum[size_t(j)] / num[size_t(j)]));
  }
  const double estimated = slope(logt, logv) / 2.0;
  std::printf("profile H %.2f: estimated %.4f\n", H, estimated);
  EXPECT_NEAR(estimated, H, 0.05);
  // And the scale: Var at tau = 2^-levels is sigma^2 2^(-2 H levels).
  EXPECT_NEAR(std::log(sum[0] / num[0]), -2.0 * H * levels * std::log(2.0), 0.1);
}

INSTANTIATE_TEST_SUITE_P(Hurst, ProfileScaling, ::testing::Values(0.3, 0.5, 0.8));

class TerrainScaling : public ::testing::TestWithParam<std::tuple<int, double>> {};

TEST_P(TerrainScaling, AlignedIncrementVarianceGrowsAsLagToTheTwoH) {
  // 2D diamond-square is not exact: the square step averages diagonal
  // neighbours at distance sqrt(2) D, so the smallest lags are biased (a
  // property of the method, seed 000 fig. 7g). Measured on lags 2^2 .. 2^7 of
  // 40 terrains of 2^9 + 1: at lag 2^7 each terrain has 2 * 5 * 4 = 40 pairs,
  // 1600 in all (relative SE 3.5%); the fit's statistical error in H is below
  // 0.01, so the 0.08 tolerance (the issue's) bounds the method's own bias.
  const auto [method, H] = GetParam();
  const double estimated = aligned_hurst_2d(method, 9, H, 40, 2, 7);
  std::printf("method %d H %.2f: estimated %.4f\n", method, H, estimated);
  EXPECT_NEAR(estimated, H, 0.08) << "method " << method;
}

INSTANTIATE_TEST_SUITE_P(
    MethodsAndHurst, TerrainScaling,
    ::testing::Combine(::testing::Values(FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS),
                       ::testing::Values(0.3, 0.5, 0.8)));


// ------------------------------------------------------------ reference points

class ReferencePoints : public ::testing::TestWithParam<int> {};

TEST_P(ReferencePoints, ValuesSurviveExactlyAtTheirNodes) {
  const int m = 3, side = (1 << m) + 1;
  std::vector<float> ref(size_t(side) * side);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) ref[size_t(j) * side + i] = float(std::sin(i * 0.7) * 3 + j * 0.25);
  ft_terrain_params p = terrain(GetParam(), 8, 0.7, 5);
  p.reference = ref.data();
  p.reference_size = side;
  const Heightfield hf = terrain::generate_terrain(p);
  const int step = 256 >> m;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      ASSERT_EQ(hf.at(i * step, j * step), ref[size_t(j) * side + i]) << i << "," << j;
  // Between the nodes the terrain is refined, not flat.
  EXPECT_NE(hf.at(step / 2, step / 2), hf.at(0, 0));
}

INSTANTIATE_TEST_SUITE_P(Methods, ReferencePoints, ::testing::Values(FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS));

TEST(ReferencePoints, ScaleFromMeanOfReferencesScalesTheDetail) {
  // With reference_scale = mean the displacements scale with mean |ref|:
  // multiplying the references by 10 multiplies the fine detail by 10 too.
  const int side = 5;
  std::vector<float> ref(size_t(side) * side), ref10(ref.size());
  for (size_t i = 0; i < ref.size(); ++i) ref[i] = 1.0f + float(i % 3), ref10[i] = 10.0f * ref[i];
  auto detail = [&](const std::vector<float>& r) {
    ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 7, 0.5, 9);
    p.reference = r.data();
    p.reference_size = side;
    p.reference_scale = FT_REFSCALE_MEAN;
    const Heightfield hf = terrain::generate_terrain(p);
    return hf.at(1, 1) - 0.25 * (hf.at(0, 0) + hf.at(2, 0) + hf.at(0, 2) + hf.at(2, 2));
  };
  EXPECT_NEAR(detail(ref10), 10.0 * detail(ref), 1e-3 * std::fabs(detail(ref10)) + 1e-5);
}

TEST(ReferencePoints, ProfileValuesSurviveExactly) {
  std::vector<float> ref = {0.0f, 2.0f, -1.0f, 0.5f, 3.0f};  // 2^2 + 1
  ft_profile_params p = terrain::default_profile_params();
  p.levels = 10;
  p.reference = ref.data();
  p.reference_size = 5;
  std::vector<float> x(1025);
  terrain::generate_profile(p, x.data(), x.size());
  for (int i = 0; i < 5; ++i) EXPECT_EQ(x[size_t(i) * 256], ref[size_t(i)]);
}

// ---------------------------------------------------------------- periodic

TEST(Periodic, OppositeEdgesAreEqualSoTilesMeetWithoutASeam) {
  for (int method : {FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS}) {
    ft_terrain_params p = terrain(method, 7, 0.6, 3);
    p.periodic = 1;
    const Heightfield hf = terrain::generate_terrain(p);
    const int n = hf.width() - 1;
    for (int k = 0; k <= n; ++k) {
      ASSERT_EQ(hf.at(k, 0), hf.at(k, n));
      ASSERT_EQ(hf.at(0, k), hf.at(n, k));
    }
  }
}

TEST(Periodic, IncrementsAcrossTheSeamAreLikeThoseInside) {
  // A tile is seamless when increments that straddle the edge (from x = n - d/2
  // to x = d/2 of the next tile) have the same variance as interior ones at
  // the same lag d. 240 terrains of 2^7 + 1, lag d = 32, all rows: 240 * 128
  // pairs per kind, relative SE of each variance sqrt(2 / 30720) = 0.8%, but
  // rows of one terrain are correlated; the 25% band below is ~5 effective SE
  // even at one effective pair per terrain and kind (SE ~ sqrt(2 / 240) = 9%
  // each, 13% for the ratio). A non-periodic terrain fails it by far: its
  // "seam" pair lies n - d = 96 apart inside it, a variance ratio of about
  // (96 / 32)^2H = 3 at H 0.5, so > 2 is ~2.5 SE from 3 (60 terrains, the
  // earlier count, left 1.3 SE: a redraw of the seeds gave 1.95).
  auto ratio = [](int periodic) {
    double seam = 0, inner = 0;
    for (int k = 0; k < 240; ++k) {
      ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 7, 0.5, 400 + k);
      p.periodic = periodic;
      const Heightfield hf = terrain::generate_terrain(p);
      const int n = 128, d = 32;
      for (int y = 0; y < n; ++y) {
        const double a = hf.at(d / 2, y) - hf.at(n - d / 2, y);
        const double b = hf.at(n / 2 + d / 2, y) - hf.at(n / 2 - d / 2, y);
        seam += a * a;
        inner += b * b;
      }
    }
    return seam / inner;
  };
  EXPECT_NEAR(ratio(1), 1.0, 0.25);
  EXPECT_GT(ratio(0), 2.0);
}

// ------------------------------------------------------------- determinism

TEST(Determinism, SameSeedGivesTheSameBitsOnAnyThreadCount) {
  for (int method : {FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS}) {
    ft_terrain_params p = terrain(method, 8, 0.7, 11);
    p.threads = 1;
    const Heightfield one = terrain::generate_terrain(p);
    for (int t : {2, 3, 8}) {
      p.threads = t;
      const Heightfield many = terrain::generate_terrain(p);
      ASSERT_EQ(std::memcmp(one.data(), many.data(), one.size() * sizeof(float)), 0) << t << " threads";
    }
  }
}

TEST(Determinism, GoldenChecksumsPinTheOutput) {
  // These values were recorded from this implementation; they change only if
  // the algorithm, the random streams or the float arithmetic change, which
  // must be a deliberate, documented decision (saved seeds would change).
  struct Case {
    int method, periodic;
    uint64_t want;
  };
  const Case cases[] = {{FT_TERRAIN_MIDPOINT, 0, 0x4d8c4dab5e3d5fe5ULL},
                        {FT_TERRAIN_ADDITIONS, 0, 0x1d3ec4a4e33dd747ULL},
                        {FT_TERRAIN_MIDPOINT, 1, 0xe8e5b81259d7d2faULL}};
  for (const Case& c : cases) {
    ft_terrain_params p = terrain(c.method, 8, 0.8, 2024);
    p.periodic = c.periodic;
    const Heightfield hf = terrain::generate_terrain(p);
    const uint64_t got = checksum(hf.data(), hf.size());
    std::printf("method %d periodic %d: 0x%016llxULL\n", c.method, c.periodic, (unsigned long long)got);
    EXPECT_EQ(got, c.want);
  }
  // The noise methods on a non-square grid (the aspect ratio is part of what is pinned).
  // Spectral synthesis goes through FFTW, which picks its codelets by the CPU's
  // SIMD level: its value is that of this project's x86-64 machines (AVX2).
  struct NoiseCase {
    int method, basis, variant;
    double warp;
    int periodic;
    uint64_t want;
  };
  const NoiseCase noise_cases[] = {
      {FT_TERRAIN_FBM, FT_BASIS_GRADIENT, FT_FBM_STANDARD, 0.0, 0, 0xbed94033a880819aULL},
      {FT_TERRAIN_FBM, FT_BASIS_SIMPLEX, FT_FBM_RIDGED, 1.5, 0, 0xf8a1eb42759adf2aULL},
      {FT_TERRAIN_FBM, FT_BASIS_CELLULAR_F1, FT_FBM_HYBRID, 0.0, 1, 0x38b860b25412bfc7ULL},
      {FT_TERRAIN_FBM, FT_BASIS_VALUE, FT_FBM_HETERO, 0.0, 0, 0x8002f56fbb5e1c1aULL},
      {FT_TERRAIN_SPECTRAL, 0, 0, 0.0, 0, 0x9fefbf3e33f3905fULL},
      {FT_TERRAIN_INTERPOLATED, 0, 0, 0.0, 0, 0x1d55f8e86a2c2bc6ULL},
      {FT_TERRAIN_INTERPOLATED, 0, 0, 0.0, 1, 0x6cdb2c9580385fdcULL}};
  for (const NoiseCase& c : noise_cases) {
    ft_terrain_params p = terrain(c.method, 8, 0.7, 2024);
    p.width = 150, p.height = 101;
    p.basis = c.basis, p.variant = c.variant, p.warp = c.warp, p.periodic = c.periodic;
    const Heightfield hf = terrain::generate_terrain(p);
    const uint64_t got = checksum(hf.data(), hf.size());
    std::printf("method %d basis %d variant %d periodic %d: 0x%016llxULL\n", c.method, c.basis, c.variant,
                c.periodic, (unsigned long long)got);
    EXPECT_EQ(got, c.want) << "method " << c.method << " basis " << c.basis << " variant " << c.variant;
  }
  std::vector<float> x(1025);
  ft_profile_params pp = terrain::default_profile_params();
  pp.seed = 2024;
  terrain::generate_profile(pp, x.data(), x.size());
  const uint64_t got = checksum(x.data(), x.size());
  std::printf("profile: 0x%016llxULL\n", (unsigned long long)got);
  EXPECT_EQ(got, 0xda88b8ce154ba34dULL);
}

TEST(Determinism, DifferentSeedsGiveDifferentTerrains) {
  const Heightfield a = terrain::generate_terrain(terrain(FT_TERRAIN_MIDPOINT, 6, 0.5, 1));
  const Heightfield b = terrain::generate_terrain(terrain(FT_TERRAIN_MIDPOINT, 6, 0.5, 2));
  EXPECT_NE(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

// ---------------------------------------------------------------- bad input

ft_status status_of(const ft_terrain_params& p, std::string* message = nullptr) {
  try {
    terrain::generate_terrain(p);
    return FT_OK;
  } catch (const Error& e) {
    if (message) *message = e.what();
    return e.status();
  }
}

TEST(BadInput, HurstOutsideZeroToOneOrNanIsRejectedWithTheRange) {
  for (double h : {-0.1, 1.01, std::nan("")}) {
    ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 4, h, 1);
    std::string msg;
    EXPECT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT) << h;
    EXPECT_NE(msg.find("hurst must be in [0, 1]"), std::string::npos) << msg;
  }
}

TEST(BadInput, SigmaMustBePositiveAndFinite) {
  for (double s : {0.0, -1.0, std::nan(""), double(INFINITY)}) {
    ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 4, 0.5, 1);
    p.sigma = s;
    EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT) << s;
  }
}

TEST(BadInput, WorldSizeMustBePositiveAndFinite) {
  for (double w : {0.0, -5.0, std::nan(""), double(INFINITY)}) {
    ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 4, 0.5, 1);
    p.world_size = w;
    std::string msg;
    EXPECT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT) << w;
    EXPECT_NE(msg.find("world_size"), std::string::npos) << msg;
  }
}

// Small settings of every method, for the checks that apply to all.
std::vector<ft_terrain_params> every_method() {
  std::vector<ft_terrain_params> all;
  for (int m : {FT_TERRAIN_MIDPOINT, FT_TERRAIN_ADDITIONS, FT_TERRAIN_FBM, FT_TERRAIN_SPECTRAL,
                FT_TERRAIN_INTERPOLATED}) {
    ft_terrain_params p = terrain(m, 5, 0.7, 3);
    p.width = 40, p.height = 24;
    all.push_back(p);
  }
  return all;
}

TEST(WorldSize, EveryMethodRecordsTheWorldSizeItWasGiven) {
  // It used to be set by the midpoint and additions branch only.
  for (ft_terrain_params p : every_method()) {
    p.world_size = 40;
    EXPECT_EQ(terrain::generate_terrain(p).world_size(), 40.0) << "method " << p.method;
  }
}

TEST(BadInput, SigmaThatCouldOverflowFloatIsRefusedBeforeAnyWork) {
  for (ft_terrain_params p : every_method()) {
    for (double s : {1e300, 1e39}) {
      p.sigma = s;
      std::string msg;
      EXPECT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT) << "method " << p.method << " sigma " << s;
      EXPECT_NE(msg.find("sigma"), std::string::npos) << msg;
      EXPECT_NE(msg.find("float range"), std::string::npos) << msg;
    }
  }
  ft_profile_params q = terrain::default_profile_params();
  q.sigma = 1e300;
  std::vector<float> x((size_t(1) << q.levels) + 1);
  EXPECT_THROW(terrain::generate_profile(q, x.data(), x.size()), Error);
}

// The bound is an upper bound: at the largest sigma it allows, every method
// makes finite heights whose range (max - min) is finite too. The message
// states that largest sigma; take it from there.
TEST(BadInput, TheLargestAllowedSigmaGivesFiniteHeights) {
  for (ft_terrain_params p : every_method()) {
    p.sigma = 1e300;
    std::string msg;
    ASSERT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT);
    const size_t at = msg.find("at most ");
    ASSERT_NE(at, std::string::npos) << msg;
    const double largest = std::strtod(msg.c_str() + at + 8, nullptr);
    ASSERT_GT(largest, 1e30) << msg;  // sane sigmas stay far inside
    p.sigma = largest * 0.999;
    const Heightfield hf = terrain::generate_terrain(p);
    const HeightStats st = hf.stats();
    EXPECT_TRUE(std::isfinite(st.min) && std::isfinite(st.max)) << "method " << p.method;
    EXPECT_TRUE(std::isfinite(float(st.max) - float(st.min))) << "method " << p.method;
  }
}

TEST(BadInput, FbmOffsetThatOverflowsTheOctaveSumIsRefused) {
  ft_terrain_params p = every_method()[2];
  p.variant = FT_FBM_HETERO;
  p.offset = 1e20;  // sum *= 1 + (n + offset) a per octave: 1e160 after 8
  std::string msg;
  EXPECT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(msg.find("offset"), std::string::npos) << msg;
}

TEST(BadInput, LevelsOutOfRangeAreRejected) {
  for (int levels : {0, -3, 16, 1000}) {
    std::string msg;
    EXPECT_EQ(status_of(terrain(FT_TERRAIN_MIDPOINT, levels, 0.5, 1), &msg), FT_ERR_INVALID_ARGUMENT);
    EXPECT_NE(msg.find("levels must be in 1..15"), std::string::npos) << msg;
  }
}

TEST(BadInput, TerrainAboveTheMemoryCapIsRefusedBeforeAllocating) {
  set_memory_cap(64 << 20);  // 64 MiB: levels 12 (16.8M samples, 67 MB) is too much
  std::string msg;
  EXPECT_EQ(status_of(terrain(FT_TERRAIN_MIDPOINT, 12, 0.5, 1), &msg), FT_ERR_TOO_LARGE);
  EXPECT_NE(msg.find("levels 12"), std::string::npos) << msg;
  EXPECT_NE(msg.find("memory cap"), std::string::npos) << msg;
  EXPECT_EQ(status_of(terrain(FT_TERRAIN_MIDPOINT, 11, 0.5, 1)), FT_OK);
  set_memory_cap(0);
}

TEST(BadInput, ReferenceGridOfTheWrongSizeIsRejected) {
  std::vector<float> ref(64, 1.0f);
  for (int size : {8, 2, 0, 513}) {
    ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 8, 0.5, 1);
    p.reference = ref.data();
    p.reference_size = size;
    std::string msg;
    EXPECT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT) << size;
    EXPECT_NE(msg.find("reference_size must be 2^m + 1"), std::string::npos) << msg;
  }
}

TEST(BadInput, NonFiniteReferenceValuesAreRejected) {
  std::vector<float> ref(9, 1.0f);
  ref[4] = std::nanf("");
  ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 4, 0.5, 1);
  p.reference = ref.data();
  p.reference_size = 3;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
}

TEST(BadInput, PeriodicTerrainNeedsAPeriodicReference) {
  std::vector<float> ref = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 4, 0.5, 1);
  p.reference = ref.data();
  p.reference_size = 3;
  p.periodic = 1;
  EXPECT_EQ(status_of(p), FT_ERR_INVALID_ARGUMENT);
}

TEST(BadInput, UninitialisedParamsAreRejected) {
  ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 4, 0.5, 1);
  p.struct_size = 0;
  std::string msg;
  EXPECT_EQ(status_of(p, &msg), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(msg.find("ft_terrain_params_init"), std::string::npos) << msg;
}

TEST(Cancellation, ProgressCallbackCanStopAGeneration) {
  ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 10, 0.5, 1);
  int calls = 0;
  p.progress = [](void* user, double fraction) -> int32_t {
    ++*static_cast<int*>(user);
    return fraction > 0.5;
  };
  p.progress_user = &calls;
  EXPECT_EQ(status_of(p), FT_ERR_CANCELLED);
  EXPECT_GE(calls, 5);
}

// A cancel in the middle of the last stage, taken by the calling thread
// while the team runs its shares of that stage (midpoint.cpp): the status
// comes back, no exception escapes a parallel region, and no later report
// follows; the fractions never go back.
TEST(Cancellation, ACancelInsideAParallelStageStopsIt) {
  ft_terrain_params p = terrain(FT_TERRAIN_MIDPOINT, 12, 0.5, 1);
  p.threads = 2;
  std::vector<double> seen;
  p.progress = [](void* user, double fraction) -> int32_t {
    static_cast<std::vector<double>*>(user)->push_back(fraction);
    return fraction > 0.8;  // the last stage spans 0.75..1
  };
  p.progress_user = &seen;
  EXPECT_EQ(status_of(p), FT_ERR_CANCELLED);
  ASSERT_FALSE(seen.empty());
  EXPECT_GT(seen.back(), 0.8);
  EXPECT_LT(seen.back(), 1.0);
  for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
}

TEST(MidpointSteps, Avx512KernelsGiveThePortableLoopsBits) {
  // The AVX-512 kernels against the portable loops, bit for bit, on rows of
  // random values: strides 2, 4 and 8, several starts x0, counts that end
  // inside a vector group and span several, and nothing written but the
  // points (the other places keep their values, 16 past the end included).
  if (!terrain::detail::steps_avx512()) GTEST_SKIP() << "no AVX-512 on this CPU (or FT_DISPATCH caps it)";
  std::vector<float> up(400), dn(400), g(40);
  uint32_t state = 12345;
  auto next = [&state] { return float(int32_t(state = state * 1664525u + 1013904223u)) * 0x1p-31f; };
  for (auto& v : up) v = next();
  for (auto& v : dn) v = next();
  for (auto& v : g) v = next();
  for (const int big : {2, 4, 8}) {
    ASSERT_TRUE(terrain::detail::steps_avx512_stride(big));
    const int half = big / 2;
    for (int x0 = half; x0 <= half + 3; ++x0)
      for (int count = 0; count <= 37; ++count) {
        const int end = x0 + big * count - half;  // one past the last point's right neighbour
        std::vector<float> row(size_t(std::max(end, x0)) + 16);
        for (auto& v : row) v = next();
        for (const bool square : {true, false}) {
          std::vector<float> a = row, b = row;
          if (square) {
            terrain::detail::square_row_avx512(a.data(), up.data(), dn.data(), x0, count, big, 0.3f, g.data());
            terrain::detail::square_row_portable(b.data(), up.data(), dn.data(), x0, count, big, half, 0.3f, g.data());
          } else {
            terrain::detail::diamond_interior_avx512(a.data(), up.data(), dn.data(), x0, count, big, 0.3f, g.data());
            terrain::detail::diamond_interior_portable(b.data(), up.data(), dn.data(), x0, count, big, half, 0.3f, g.data());
          }
          ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0)
              << (square ? "square" : "diamond") << " big " << big << " x0 " << x0 << " count " << count;
          for (int x = 0; x < int(row.size()); ++x) {
            const bool point = x >= x0 && (x - x0) % big == 0 && (x - x0) / big < count;
            if (!point) {
              ASSERT_EQ(a[size_t(x)], row[size_t(x)]) << "big " << big << " x " << x;
            }
          }
        }
      }
  }
}

}  // namespace
}  // namespace ft
