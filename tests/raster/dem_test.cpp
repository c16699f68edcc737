// SPDX-License-Identifier: GPL-3.0-or-later
// A real DEM (Luxembourg, from Debian's r-cran-terra; see fetch_dem.sh) read
// through GDAL and refined: its samples survive at their nodes, and the
// refined terrain's increment variance continues the DEM's own scaling line
// below its pixel size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "refine/dem_refine.hpp"

namespace ft {
namespace {

std::string dem_path() {
  const char* p = std::getenv("FT_REAL_DEM");
  return p ? p : "";
}

// Mean squared increment at `lag` samples, rows and columns pooled: the
// test's own reference, independent of the library's estimators.
double increment_variance(const Heightfield& hf, int lag) {
  double sum = 0;
  size_t n = 0;
  for (int y = 0; y < hf.height(); ++y)
    for (int x = 0; x < hf.width(); ++x) {
      if (x + lag < hf.width()) sum += std::pow(double(hf.at(x + lag, y)) - hf.at(x, y), 2), ++n;
      if (y + lag < hf.height()) sum += std::pow(double(hf.at(x, y + lag)) - hf.at(x, y), 2), ++n;
    }
  return sum / double(n);
}

// Every test reads the DEM: each fails with the reason when it is not there
// (a fatal failure in SetUp skips the body, which would read "").
class RealDem : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_FALSE(dem_path().empty()) << "FT_REAL_DEM is not set (run through ctest: the fixture fetches the DEM)";
  }
};

TEST_F(RealDem, ReadsWithItsGeoreferenceAndCountsItsNodata) {
  try {
    io::read_heightfield(dem_path());
    FAIL() << "the DEM's nodata was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("3942 nodata samples of 8550"), std::string::npos) << e.what();
  }
  const Heightfield dem = io::read_heightfield(dem_path(), io::NodataPolicy::keep);
  ASSERT_EQ(dem.width(), 95);
  ASSERT_EQ(dem.height(), 90);
  EXPECT_NE(dem.georef().crs_wkt.find("WGS 84"), std::string::npos);
  EXPECT_NEAR(dem.georef().transform[1], 1.0 / 120, 1e-12);  // 30 arc-seconds
  // 94 pixels of 1/120 degree at the centre latitude 49.8167 on WGS 84's
  // semi-major axis: 94 x 927.66 x cos(49.8167 deg) = 56 182 m.
  EXPECT_NEAR(dem.world_size(), 94 * 6378137 * M_PI / 180 / 120 * std::cos(49.81666666666666 * M_PI / 180), 1e-6);
  const HeightStats s = [&] {
    Heightfield filled = io::read_heightfield(dem_path(), io::NodataPolicy::fill);
    return filled.stats();
  }();
  EXPECT_EQ(s.min, 141.0);  // gdalinfo -stats: Min=141.000 Max=547.000
  EXPECT_EQ(s.max, 547.0);
}

TEST_F(RealDem, RefinementKeepsTheDemAtItsNodes) {
  const Heightfield dem = io::read_heightfield(dem_path(), io::NodataPolicy::keep);
  refine::DemRefineConfig c;
  c.levels_added = 3;
  const refine::DemRefineResult r = refine::refine_dem(dem, c);
  ASSERT_EQ(r.window_side, 33);  // the largest 2^m + 1 square inside Luxembourg
  ASSERT_EQ(r.terrain.width(), 257);
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x)
      ASSERT_EQ(r.terrain.at(8 * x, 8 * y), dem.at(r.window_x + x, r.window_y + y)) << x << ", " << y;
  // The refined pixels are 8 times smaller, centred on the DEM's samples.
  const auto& g = dem.georef().transform;
  const auto& f = r.terrain.georef().transform;
  EXPECT_NEAR(f[1], g[1] / 8, 1e-15);
  EXPECT_NEAR(f[0] + 0.5 * f[1], g[0] + (r.window_x + 0.5) * g[1], 1e-12);
  EXPECT_NEAR(f[3] + 0.5 * f[5], g[3] + (r.window_y + 0.5) * g[5], 1e-12);
}

// The continuation. The DEM's scaling line is V(r) = V1 r^(2H), r in DEM
// pixels, with V1 its mean squared increment at one pixel and H the slope
// the refiner measured (and printed). Tolerances, in log2 of the variance:
//  - 0.2 at and above one DEM pixel. Sampling: over 4 seeds the refined
//    variance at a given lag varies by 0.03 (sd, measured); 3 sd = 0.1. The
//    scheme: diamond-square conditions each new point on 4 neighbours, not
//    on the whole field, and its variogram departs from a power law by about
//    0.1 over a few octaves (its H estimates fall 0.05 short; README,
//    Accuracy); 0.1 more. A sigma 7% off in standard deviation (0.2 in log2
//    of the variance) at the junction is caught.
//  - plus 2 x 2 sigma_H |log2 r| below one pixel: the line is extrapolated
//    with a slope 2H known to sigma_H (the estimate's standard error), so at
//    r = 2^-k its height is uncertain by 2 sigma_H k; two of those.
// Above one pixel the refined terrain must keep the DEM's own (measured)
// variances, not the line's: the DEM is not exactly a power law there.
TEST_F(RealDem, RefinedScalingContinuesTheDemsLineAcrossTheJunction) {
  const Heightfield dem = io::read_heightfield(dem_path(), io::NodataPolicy::keep);
  constexpr int K = 3;
  const std::vector<uint64_t> seeds = {1, 2, 3, 4};
  std::vector<double> mean(K + 4, 0.0);  // log2 variance at fine lags 2^0 .. 2^(K + 3)
  refine::DemRefineResult r;
  for (uint64_t seed : seeds) {
    refine::DemRefineConfig c;
    c.levels_added = K;
    c.seed = seed;
    r = refine::refine_dem(dem, c);
    for (int k = 0; k < K + 4; ++k) mean[k] += std::log2(increment_variance(r.terrain, 1 << k)) / double(seeds.size());
  }
  ASSERT_TRUE(r.hurst_measured && r.sigma_measured);
  EXPECT_NEAR(r.hurst, 0.356, 0.01);  // printed by fracterra refine on this DEM
  Heightfield window(r.window_side, r.window_side);
  for (int y = 0; y < r.window_side; ++y)
    for (int x = 0; x < r.window_side; ++x) window.at(x, y) = dem.at(r.window_x + x, r.window_y + y);
  const double sigma_h = r.estimate.std_error;
  ASSERT_GT(sigma_h, 0.0);
  for (int k = 0; k <= K; ++k) {  // added lags, up to the junction (one DEM pixel)
    const double log2_r = k - K;
    const double line = std::log2(r.v1) + 2 * r.hurst * log2_r;
    EXPECT_NEAR(mean[k], line, 0.2 + 4 * sigma_h * std::abs(log2_r)) << "lag 2^" << log2_r << " DEM pixels";
  }
  for (int k = K + 1; k < K + 4; ++k)  // DEM lags 2, 4, 8 pixels
    EXPECT_NEAR(mean[k], std::log2(increment_variance(window, 1 << (k - K))), 0.2) << "lag " << (1 << (k - K));
}

}  // namespace
}  // namespace ft
