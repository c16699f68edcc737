// SPDX-License-Identifier: GPL-3.0-or-later
// The same terrain at every resolution: the same seed and world parameters
// give the same landform at any size, and more levels or samples only add
// detail (issue 24, part 2).
//
// Midpoint displacement never moves a point once placed, and stage s's draws
// are keyed by the point's place in stage s's own grid: a terrain of levels L
// is the terrain of levels L + 2 at every 4th sample, bit for bit (plain,
// periodic, from a reference grid, and as windows at any lod). So is the
// Voss profile. The other methods add to old points (additions,
// interpolated) or hold finer waves (spectral) at a larger size, so the
// larger terrain's samples at the smaller one's places agree with it up to
// the finer detail: correlation bounds, derived below, over several seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "terrain/terrain.hpp"

using namespace ft;

namespace {

ft_terrain_params params(int method, uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = method;
  p.hurst = 0.65;
  p.seed = seed;
  p.threads = 2;
  return p;
}

// Every k-th sample of `fine` (k-th row, k-th column) from the origin: the
// places of the coarse terrain's samples in the fine one.
std::vector<float> every_kth(const Heightfield& fine, int k, int w, int h) {
  std::vector<float> out(size_t(w) * size_t(h));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) out[size_t(j) * size_t(w) + size_t(i)] = fine.at(i * k, j * k);
  return out;
}

double correlation(const float* a, const float* b, size_t n) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
  ma /= double(n), mb /= double(n);
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < n; ++i) {
    const double da = a[i] - ma, db = b[i] - mb;
    sab += da * db, saa += da * da, sbb += db * db;
  }
  return sab / std::sqrt(saa * sbb);
}

// The coarse terrain against the fine one's samples at its places.
double node_correlation(const Heightfield& coarse, const Heightfield& fine, int k) {
  const std::vector<float> s = every_kth(fine, k, coarse.width(), coarse.height());
  return correlation(coarse.data(), s.data(), s.size());
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

// How many of the coarse terrain's samples differ in any bit from the fine
// one's at the same place.
size_t differing_nodes(const Heightfield& coarse, const Heightfield& fine, int k) {
  const std::vector<float> s = every_kth(fine, k, coarse.width(), coarse.height());
  size_t bad = 0;
  for (size_t i = 0; i < s.size(); ++i) bad += !same_bits(s[i], coarse.data()[i]);
  return bad;
}

// A 5 x 5 periodic-compatible reference grid (last row and column repeat the first).
std::vector<float> reference_grid() {
  std::vector<float> r(25);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) r[size_t(j) * 5 + size_t(i)] = float(((i % 4) * 7 + (j % 4) * 3) % 5) - 2.0f;
  return r;
}

const uint64_t kSeeds[] = {1, 1234, 77, 2024};

// The terrain of p at the size `coarse` sets in it, and at the size `fine` sets.
template <class Coarse, class Fine>
std::pair<Heightfield, Heightfield> two_sizes(ft_terrain_params p, Coarse coarse, Fine fine) {
  coarse(p);
  Heightfield a = terrain::generate_terrain(p);
  fine(p);
  return {std::move(a), terrain::generate_terrain(p)};
}

void levels(ft_terrain_params& p, int l) { p.levels = l; }

}  // namespace

TEST(Resolution, MidpointLevelsLEqualLevelsLPlus2AtTheirNodesBitForBit) {
  const std::vector<float> ref = reference_grid();
  for (uint64_t seed : kSeeds)
    for (int periodic : {0, 1})
      for (bool with_reference : {false, true}) {
        ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, seed);
        p.periodic = periodic;
        if (with_reference) p.reference = ref.data(), p.reference_size = 5;
        const auto [coarse, fine] = two_sizes(p, [](auto& q) { levels(q, 7); }, [](auto& q) { levels(q, 9); });
        EXPECT_EQ(differing_nodes(coarse, fine, 4), 0u)
            << "seed " << seed << (periodic ? " periodic" : "") << (with_reference ? " reference" : "");
      }
}

TEST(Resolution, MidpointWindowsOfLevelsLPlus2AreLevelsLAtTheirNodes) {
  // Windows of the levels-11 terrain (never made whole here): at lod 0, its
  // every 4th sample is the levels-9 terrain's; at lod 2 a window of it is
  // the same window of the levels-9 terrain, both bit for bit.
  const std::vector<float> ref = reference_grid();
  for (int periodic : {0, 1})
    for (bool with_reference : {false, true}) {
      ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, 1234);
      p.periodic = periodic;
      if (with_reference) p.reference = ref.data(), p.reference_size = 5;
      p.levels = 9;
      const Heightfield coarse = terrain::generate_terrain(p);
      const std::string what = std::string(periodic ? "periodic" : "plain") + (with_reference ? " reference" : "");
      p.levels = 11;
      // lod 0: 401 x 301 samples from (1200, 804): every 4th row and column
      // are the coarse samples from (300, 201).
      const int64_t x0 = 1200, y0 = 804;
      const Heightfield win = terrain::generate_terrain_window(p, 0, x0, y0, 401, 301);
      size_t bad = 0;
      for (int j = 0; j < 301; j += 4)
        for (int i = 0; i < 401; i += 4)
          bad += !same_bits(win.at(i, j), coarse.at(int((x0 + i) / 4), int((y0 + j) / 4)));
      EXPECT_EQ(bad, 0u) << what << " lod 0";
      // lod 2: the window (37, 450) 100 x 63 of the levels-9 terrain.
      const Heightfield lod = terrain::generate_terrain_window(p, 2, 37, 450, 100, 63);
      bad = 0;
      for (int j = 0; j < 63; ++j)
        for (int i = 0; i < 100; ++i) bad += !same_bits(lod.at(i, j), coarse.at(37 + i, 450 + j));
      EXPECT_EQ(bad, 0u) << what << " lod 2";
    }
}

TEST(Resolution, ProfileLevelsLEqualLevelsLPlus2AtTheirNodesBitForBit) {
  for (uint64_t seed : kSeeds) {
    ft_profile_params p = terrain::default_profile_params();
    p.seed = seed;
    p.hurst = 0.65;
    p.levels = 8;
    std::vector<float> coarse(257), fine(1025);
    terrain::generate_profile(p, coarse.data(), coarse.size());
    p.levels = 10;
    terrain::generate_profile(p, fine.data(), fine.size());
    for (size_t i = 0; i < coarse.size(); ++i) ASSERT_EQ(coarse[i], fine[4 * i]) << "seed " << seed << " at " << i;
  }
}

TEST(Resolution, MidpointStagesNeverDependOnTheLevelsBelowThem) {
  // 8, 9 and 10 levels agree pairwise (1 and 2 levels apart) at their shared nodes.
  for (int periodic : {0, 1}) {
    ft_terrain_params p = params(FT_TERRAIN_MIDPOINT, 1234);
    p.periodic = periodic;
    std::vector<Heightfield> t;
    for (int levels : {8, 9, 10}) p.levels = levels, t.push_back(terrain::generate_terrain(p));
    EXPECT_EQ(differing_nodes(t[0], t[1], 2), 0u) << periodic;
    EXPECT_EQ(differing_nodes(t[1], t[2], 2), 0u) << periodic;
    EXPECT_EQ(differing_nodes(t[0], t[2], 4), 0u) << periodic;
  }
}

// ------------------------------------------------------------ the correlations
//
// A larger terrain = the smaller one at the shared places + E, E the detail
// the smaller one lacks, independent of it; then r = 1 / sqrt(1 + vE / vX)
// ~ 1 - vE / (2 vX), vX the smaller terrain's variance over its samples. The
// bound 0.99 of the issue needs vE / vX < 0.02. At H 0.65 (the issue's
// measure) the estimates below put 1 - r near 0.001-0.003; the finer detail
// grows as H falls (at H 0.3 the same sizes give 1 - r ~ 0.02-0.05 for
// every method that adds to old points: that is detail, not a moved
// landform), so the bound is checked at H 0.65 and 0.8.

TEST(Resolution, AdditionsLevelsLPlus2CorrelateWithLevelsLAtTheirNodes) {
  // Stages <= L are the same bits at both sizes; stages L + 1 and L + 2 add
  // delta^2 = 2^-(2s - 1)H + 2^-2sH (sigma 1, the square and diamond
  // additions) to every old node: vE = 0.0027 at L = 7, H 0.65, and the
  // terrain's variance is of the order of its first stages' (~1), so
  // 1 - r ~ 0.0013 / vX. The tighter check: 1 - r within 1.5x of
  // vE / (2 vX) with vX measured (16641 nodes: the sample vE scatters by
  // ~1%, r's own sampling by a few %).
  for (uint64_t seed : kSeeds)
    for (double hurst : {0.65, 0.8})
      for (int periodic : {0, 1}) {
        ft_terrain_params p = params(FT_TERRAIN_ADDITIONS, seed);
        p.hurst = hurst;
        p.periodic = periodic;
        const auto [coarse, fine] = two_sizes(p, [](auto& q) { levels(q, 7); }, [](auto& q) { levels(q, 9); });
        double ve = 0;
        for (int s = 8; s <= 9; ++s) ve += std::pow(2.0, -(2 * s - 1) * hurst) + std::pow(2.0, -2 * s * hurst);
        const double vx = coarse.stats().std * coarse.stats().std;
        const double r = node_correlation(coarse, fine, 4);
        EXPECT_GE(r, 0.99) << "seed " << seed << " H " << hurst << (periodic ? " periodic" : "");
        EXPECT_LE(1.0 - r, 1.5 * ve / (2.0 * vx)) << "seed " << seed << " H " << hurst;
      }
}

TEST(Resolution, InterpolatedSamplesTheSameFieldAtFourTimesTheSamples) {
  // The lattices are fractions of the extent: cycle k has ceil(a r^-k) + 1
  // nodes along a side that is a of the longer one (periodic: round(a r^-k)),
  // its draws keyed by node, its delta sigma r^kH; only the last cycle lands
  // on the samples. The larger terrain adds its finer cycles to every node
  // (vE ~ sum of sigma^2 spacing^2H over them: ~1e-3 at H 0.65 for 4x the
  // samples) and re-interpolates the last lattices through them: measured
  // 1 - r of 0.0005-0.008 for these settings over seeds 1-3 with the CLI.
  for (uint64_t seed : kSeeds)
    for (double lacunarity : {2.0, 2.7})
      for (int periodic : {0, 1}) {
        ft_terrain_params p = params(FT_TERRAIN_INTERPOLATED, seed);
        p.lacunarity = lacunarity;
        p.periodic = periodic;
        // Non-square (the aspect ratio is part of the world); non-periodic
        // samples span (width - 1) spacings, periodic ones width.
        const auto [coarse, fine] = two_sizes(
            p, [](auto& q) { q.width = 300, q.height = 200; },
            [&](auto& q) { q.width = periodic ? 1200 : 1197, q.height = periodic ? 800 : 797; });
        EXPECT_GE(node_correlation(coarse, fine, 4), 0.99)
            << "seed " << seed << " lacunarity " << lacunarity << (periodic ? " periodic" : "");
      }
}

TEST(Resolution, SpectralHoldsTheSameWavesAtFourTimesTheSamples) {
  // The same coefficient for the same wave number, amplitudes in cycles
  // across the terrain: the larger one's samples at the smaller one's places
  // are the smaller one plus its waves beyond |k| = 128 (plus the smaller's
  // Nyquist row and column, made real or mirrored). Their power over the
  // smaller one's, sum 2 f^-(2H + 2) for f > 128 over the whole sum, is
  // ~4 pi / (2H) 128^-2H / 16 ~ 1e-3 at H 0.65: 1 - r ~ 5e-4 (measured
  // 0.999 for seed 1234). Before the fix, waves of negative ky were keyed
  // by their row in the FFT array, ky + h, and moved with h: r was 0.87.
  for (uint64_t seed : kSeeds)
    for (double hurst : {0.65, 0.8}) {
      ft_terrain_params p = params(FT_TERRAIN_SPECTRAL, seed);
      p.hurst = hurst;
      const auto [coarse, fine] = two_sizes(p, [](auto& q) { q.width = 256, q.height = 170; },
                                            [](auto& q) { q.width = 1024, q.height = 680; });
      EXPECT_GE(node_correlation(coarse, fine, 4), 0.99) << "seed " << seed << " H " << hurst;
      // sigma is the std of the waves up to 256 cycles, at every size: the
      // expected std of 256 and 1024 samples differ by 0.05% at H 0.65 (one
      // field's std scatters by tens of percent with its few lowest waves,
      // but the two share them and differ by their finer waves' power, ~1e-3
      // of the variance): 3% is the same std. Before, each size was scaled
      // to its own expected power.
      EXPECT_NEAR(fine.stats().std / coarse.stats().std, 1.0, 0.03) << "seed " << seed << " H " << hurst;
    }
}

TEST(Resolution, FbmAndMandelbrotSampleTheSameField) {
  // fbm's lattice coordinates are x / width (periodic and not), so 4x the
  // width puts every 4th sample at the same place: the same octaves give
  // the same values up to float rounding of the coordinates. Mandelbrot's
  // plane spans (width - 1) spacings; its supersampling averages k^2 points
  // within a sample's cell, finer at the larger size (anti-aliasing detail).
  for (uint64_t seed : kSeeds)
    for (int periodic : {0, 1}) {
      ft_terrain_params p = params(FT_TERRAIN_FBM, seed);
      p.periodic = periodic;
      p.width = p.height = 256;
      const Heightfield coarse = terrain::generate_terrain(p);
      p.width = p.height = 1024;
      EXPECT_GE(node_correlation(coarse, terrain::generate_terrain(p), 4), 0.999) << "seed " << seed << " periodic " << periodic;
    }
  ft_terrain_params m = params(FT_TERRAIN_MANDELBROT, 1);
  m.width = m.height = 257;
  const Heightfield coarse = terrain::generate_terrain(m);
  m.width = m.height = 1025;
  EXPECT_GE(node_correlation(coarse, terrain::generate_terrain(m), 4), 0.99);
}
