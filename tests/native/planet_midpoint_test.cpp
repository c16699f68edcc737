// SPDX-License-Identifier: GPL-3.0-or-later
// Midpoint displacement on the cube-sphere (planet/midpoint_sphere.hpp):
// shared edges, patches against the whole, levels against levels, thread
// counts, the spread against the fBm planet's, H from the variogram along
// great circles (the rows of a face) at a face's centre and near a cube
// corner, the mesh and the sea. References are the planet's own whole faces
// and statistics over seed ensembles; each test says how it was seen to fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "planet/cube_sphere.hpp"
#include "planet/equirect.hpp"
#include "planet/planet.hpp"
#include "planet_edges.hpp"

namespace ft::planet {
namespace {

PlanetConfig midpoint(uint64_t seed, double hurst = 0.8) {
  PlanetConfig c;
  c.method = kMethodMidpoint;
  c.fbm.seed = seed;
  c.fbm.hurst = hurst;
  c.fbm.sigma = 4000;
  return c;
}

std::vector<Heightfield> whole_faces(const Planet& planet, int level) {
  const int32_t side = int32_t((int64_t(1) << level) + 1);
  std::vector<Heightfield> faces;
  for (int f = 0; f < 6; ++f) faces.push_back(face_patch(planet, level, f, 0, 0, side, side));
  return faces;
}

uint32_t bits(float x) { return std::bit_cast<uint32_t>(x); }

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]), my += std::log(y[i]);
  mx /= double(x.size()), my /= double(x.size());
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double a = std::log(x[i]) - mx, b = std::log(y[i]) - my;
    sxy += a * b, sxx += a * a;
  }
  return sxy / sxx;
}

TEST(PlanetMidpoint, SharedEdgeSamplesAreBitIdentical) {
  // Every edge and corner sample against the same sample on each other face
  // it lies on. (Seen to fail: keying the edge vertices' Gaussians by
  // (face, i, j) instead of their cube point made 3024 of 3120 pairs differ.
  // Summing their parents in face order instead of opposite pairs did not:
  // the double sums' last-bit differences vanish in the float heights.)
  for (uint64_t seed : {1u, 2u}) {
    const Planet planet(midpoint(seed));
    const int level = 6;
    const int64_t n = 64;
    const std::vector<Heightfield> faces = whole_faces(planet, level);
    int pairs = 0;
    for (int f = 0; f < 6; ++f)
      for (int64_t j = 0; j <= n; ++j)
        for (int64_t i = 0; i <= n; ++i) {
          if (i != 0 && j != 0 && i != n && j != n) continue;
          const CubePoint p = cube_point(f, i, j, n);
          for (int g = 0; g < 6; ++g) {
            int64_t gi, gj;
            if (g == f || !face_sample(p, g, n, &gi, &gj)) continue;
            ++pairs;
            EXPECT_EQ(bits(faces[size_t(f)].at(int32_t(i), int32_t(j))),
                      bits(faces[size_t(g)].at(int32_t(gi), int32_t(gj))))
                << "face " << f << " (" << i << ", " << j << ") and face " << g << " (" << gi << ", " << gj << ")";
          }
        }
    EXPECT_EQ(pairs, 6 * (4 * int(n - 1) + 8));
  }
}

TEST(PlanetMidpoint, GradientAcrossAnEdgeIsAsContinuousAsInsideAFace) {
  // As PlanetCube's for fBm: for every edge sample e shared by faces A and
  // B (not a corner), the second difference across the edge, h(b1) - 2 h(e)
  // + h(a1), against the same one sample inside A, h(e) - 2 h(a1) + h(a2)
  // (a1 = e - 2 n_B, b1 = e - 2 n_A in cube units). (The first differences'
  // ratio is 1 by construction here: with both orderings of A and B each
  // step across an edge is also counted as a step inside.) Level 7, 4
  // seeds, 12 edges x 127 samples x 2 orderings: ~12000 differences, RMS
  // within ~1.5 %; the finest displacements dominate and are alike on both
  // sides. Tolerance 8 %, the fBm test's. Measured 1.05. (Seen to fail: an
  // edge vertex's centre beyond the edge replaced by a second copy of the
  // one on its own face gave 1.41.)
  const int level = 7;
  const int64_t n = 128;
  double across2 = 0, inside2 = 0;
  for (uint64_t seed : {11u, 12u, 13u, 14u}) {
    const std::vector<Heightfield> faces = whole_faces(Planet(midpoint(seed, 0.6)), level);
    auto h = [&](const CubePoint& p) {
      int64_t i, j;
      const int g = locate(p, n, &i, &j);
      return double(faces[size_t(g)].at(int32_t(i), int32_t(j)));
    };
    for_each_edge_step(n, [&](const CubePoint& e, const CubePoint& a1, const CubePoint& a2, const CubePoint& b1) {
      const double he = h(e), ha1 = h(a1), ha2 = h(a2), hb1 = h(b1);
      across2 += (hb1 - 2 * he + ha1) * (hb1 - 2 * he + ha1);
      inside2 += (he - 2 * ha1 + ha2) * (he - 2 * ha1 + ha2);
    });
  }
  const double r2 = std::sqrt(across2 / inside2);
  RecordProperty("second_difference_ratio", std::to_string(r2));
  EXPECT_NEAR(r2, 1.0, 0.08);
}

TEST(PlanetMidpoint, PatchesEqualTheWholeAndCoarserLevelsAreSubsets) {
  // Patches computed from their own footprint's ancestors (inside a face,
  // on an edge, at a corner, one sample) against the whole faces; level L
  // against every other sample of level L + 1; at level 23, a patch against
  // a larger one around it and against every other sample of level 24.
  // (Seen to fail: a halo of one sample instead of two in add_parents read
  // a sample never computed, FT_ERR_INTERNAL "was not computed"; displacing
  // the old nodes again at each level, as Feder's additions do, made the
  // first patch differ from the whole.)
  PlanetConfig c = midpoint(5);
  c.threads = 2;
  const Planet planet(c);
  const int level = 7;
  const int32_t side = 129;
  const std::vector<Heightfield> whole = whole_faces(planet, level), coarse = whole_faces(planet, level - 1);
  for (int f = 0; f < 6; ++f) {
    for (auto [x0, y0, w, h] : std::vector<std::array<int32_t, 4>>{
             {0, 0, 7, 9}, {120, 100, 9, 29}, {17, 33, 31, 1}, {128, 128, 1, 1}, {0, 61, 3, 3}, {64, 64, 1, 1}}) {
      const Heightfield part = face_patch(planet, level, f, x0, y0, w, h);
      for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x)
          ASSERT_EQ(bits(part.at(x, y)), bits(whole[size_t(f)].at(x0 + x, y0 + y)))
              << "face " << f << " patch at (" << x0 << ", " << y0 << ") sample (" << x << ", " << y << ")";
    }
    for (int32_t y = 0; y < side / 2 + 1; ++y)
      for (int32_t x = 0; x < side / 2 + 1; ++x)
        ASSERT_EQ(bits(coarse[size_t(f)].at(x, y)), bits(whole[size_t(f)].at(2 * x, 2 * y)));
  }
  const int64_t x0 = 4194000, y0 = 4194300;
  const Heightfield deep = face_patch(planet, 23, 4, x0, y0, 16, 16);
  const Heightfield around = face_patch(planet, 23, 4, x0 - 5, y0 - 7, 40, 30);
  const Heightfield finer = face_patch(planet, 24, 4, 2 * x0, 2 * y0, 31, 31);
  for (int32_t y = 0; y < 16; ++y)
    for (int32_t x = 0; x < 16; ++x) {
      ASSERT_EQ(bits(deep.at(x, y)), bits(around.at(x + 5, y + 7)));
      ASSERT_EQ(bits(deep.at(x, y)), bits(finer.at(2 * x, 2 * y)));
    }
  // At a corner of face 2, level 20: the three faces meeting there agree.
  const int64_t n = int64_t(1) << 20;
  const Heightfield corner = face_patch(planet, 20, 2, n - 3, n - 3, 4, 4);
  for (int32_t y = 0; y < 4; ++y)
    for (int32_t x = 0; x < 4; ++x) {
      if (x != 3 && y != 3) continue;
      const CubePoint p = cube_point(2, n - 3 + x, n - 3 + y, n);
      for (int g = 0; g < 6; ++g) {
        int64_t gi, gj;
        if (g == 2 || !face_sample(p, g, n, &gi, &gj)) continue;
        ASSERT_EQ(bits(corner.at(x, y)), bits(face_patch(planet, 20, g, gi, gj, 1, 1).at(0, 0))) << g;
      }
    }
}

TEST(PlanetMidpoint, SameBitsOnAnyThreadCount) {
  std::vector<uint32_t> ref;
  for (int threads : {1, 2, 3}) {
    PlanetConfig c = midpoint(9, 0.6);
    c.threads = threads;
    const Planet planet(c);
    const Heightfield hf = face_patch(planet, 9, 1, 100, 0, 300, 200);
    std::vector<uint32_t> got;
    for (int64_t i = 0; i < int64_t(hf.width()) * hf.height(); ++i) got.push_back(bits(hf.data()[i]));
    if (ref.empty()) ref = got;
    else EXPECT_EQ(got, ref) << threads << " threads";
  }
}

// The rows of a face are arcs of great circles (a face's row is the plane
// through the centre and the line t = const). Sums over `seeds` planets of
// squared differences of samples k = 1, 2, 4 .. 64 apart along the rows of
// a 513 x 32 patch, and the mean angle between them.
struct RowVariogram {
  std::vector<double> angle, var;
};
RowVariogram row_variogram(double hurst, int level, int face, int64_t x0, int64_t y0, int seeds) {
  RowVariogram v;
  const int64_t n = int64_t(1) << level;
  const int32_t w = 513, h = 32;
  for (int l = 0; l < 7; ++l) {
    const int k = 1 << l;
    double a = 0, count = 0;
    for (int64_t j = 0; j < h; ++j)
      for (int64_t i = 0; i + k < w; ++i) {
        const auto p = unit_vector(cube_point(face, x0 + i, y0 + j, n)),
                   q = unit_vector(cube_point(face, x0 + i + k, y0 + j, n));
        const double c[3] = {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
        a += std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
        count += 1;
      }
    v.angle.push_back(a / count);
    v.var.push_back(0.0);
  }
  for (int s = 0; s < seeds; ++s) {
    const Planet planet(midpoint(uint64_t(40 + s), hurst));
    const Heightfield hf = face_patch(planet, level, face, x0, y0, w, h);
    for (int l = 0; l < 7; ++l) {
      const int k = 1 << l;
      double sum = 0, count = 0;
      for (int32_t j = 0; j < h; ++j)
        for (int32_t i = 0; i + k < w; ++i) {
          const double d = double(hf.at(i + k, j)) - hf.at(i, j);
          sum += d * d, count += 1;
        }
      v.var[size_t(l)] += sum / count / seeds;
    }
  }
  return v;
}

TEST(PlanetMidpoint, GreatCircleVariogramGivesHAtAFaceCentreAndNearACorner) {
  // Var[h(a) - h(b)] ~ angle^(2H) along the rows of a level-14 face (spacing
  // 1.2e-4 radians at the centre, 2.3 times less at a corner), lags 1..64
  // samples, 8 seeds, 513 x 32 samples at the centre of face 4 and at the
  // corner of face 0. Tolerance 0.1 on H, the flat variogram's (noise_test:
  // Interpolated). The distance-based scaling makes the variogram the same
  // function of the angle at both places: their ratio at matched angles
  // (interpolated in log-log) within 20 % (8 seeds of 16k increments at lag
  // 1, but only 8 x 32 rows' worth of independent large scales at lag 64).
  // Measured: H 0.47 and 0.48 (H 0.5), 0.81 and 0.84 (H 0.8); ratios 0.91
  // and 1.08. (Seen to fail: without the local scale (1 + s^2 + t^2)^(-3H/4)
  // the ratio was 2.0 and more.)
  for (double H : {0.5, 0.8}) {
    const int level = 14;
    const int64_t n = int64_t(1) << level;
    const RowVariogram centre = row_variogram(H, level, 4, n / 2 - 256, n / 2 - 16, 8);
    const RowVariogram corner = row_variogram(H, level, 0, 0, 0, 8);
    const double hc = 0.5 * slope(centre.angle, centre.var), hk = 0.5 * slope(corner.angle, corner.var);
    // The corner's variogram at the centre's lags (its angles are smaller: interpolate log-log within range).
    double ratio = 0;
    int used = 0;
    for (size_t l = 0; l < centre.angle.size(); ++l) {
      const double a = centre.angle[l];
      for (size_t m = 0; m + 1 < corner.angle.size(); ++m)
        if (corner.angle[m] <= a && a <= corner.angle[m + 1]) {
          const double t = std::log(a / corner.angle[m]) / std::log(corner.angle[m + 1] / corner.angle[m]);
          const double v = std::exp(std::log(corner.var[m]) + t * std::log(corner.var[m + 1] / corner.var[m]));
          ratio += v / centre.var[l], ++used;
        }
    }
    ratio /= used;
    RecordProperty("H_centre_" + std::to_string(H), std::to_string(hc));
    RecordProperty("H_corner_" + std::to_string(H), std::to_string(hk));
    RecordProperty("corner_over_centre_" + std::to_string(H), std::to_string(ratio));
    EXPECT_NEAR(hc, H, 0.1);
    EXPECT_NEAR(hk, H, 0.1);
    EXPECT_GE(used, 4);
    EXPECT_NEAR(ratio, 1.0, 0.2) << "H = " << H;
  }
}

TEST(PlanetMidpoint, HeightsSpreadAsMuchAsTheFbmPlanets) {
  // sigma means the same for both methods at the default H 0.8: the std of
  // the heights of a level-6 cube-sphere (all faces) averaged over 16 seeds,
  // midpoint against fBm (12 octaves, frequency 1.5), within 15 % (one
  // planet's std varies by ~30 % from seed to seed, its continents are few;
  // 16 seeds give ~8 %). At H 0.5 the midpoint spreads more (the fBm's
  // octave sum is normalised by its amplitudes, the displacements are not):
  // between 1 and 2 times. Measured: 1.03 and 1.42. (Seen to fail:
  // kMidpointUnit 0.25 gave 1.28 at H 0.8.)
  for (double H : {0.5, 0.8}) {
    double sm = 0, sf = 0;
    for (uint64_t seed = 60; seed < 76; ++seed) {
      PlanetConfig f = midpoint(seed, H);
      f.method = kMethodFbm;
      for (const PlanetConfig& c : {midpoint(seed, H), f}) {
        double s = 0, s2 = 0, count = 0;
        for (const Heightfield& hf : whole_faces(Planet(c), 6))
          for (int64_t i = 0; i < int64_t(hf.width()) * hf.height(); ++i)
            s += hf.data()[i], s2 += double(hf.data()[i]) * hf.data()[i], count += 1;
        (c.method == kMethodMidpoint ? sm : sf) += std::sqrt(s2 / count - (s / count) * (s / count)) / 16;
      }
    }
    RecordProperty("std_ratio_" + std::to_string(H), std::to_string(sm / sf));
    if (H == 0.8) EXPECT_NEAR(sm / sf, 1.0, 0.15);
    else EXPECT_TRUE(sm / sf > 1.0 && sm / sf < 2.0) << sm / sf;
  }
}

TEST(PlanetMidpoint, MeshEquirectAndSeaUseTheCubeSamples) {
  // The mesh's heights are the faces' samples; the equirect map's pixel at
  // a face's centre direction is that sample (interpolation at a node); a
  // sea fraction covers that share of the interpolated sphere.
  PlanetConfig c = midpoint(3);
  c.sea = kSeaFraction;
  c.sea_fraction = 0.6;
  const Planet planet(c);
  std::vector<float> heights;
  const Mesh m = cube_sphere_mesh(planet, 4, 1.0, &heights);
  const std::vector<Heightfield> faces = whole_faces(planet, 4);
  ASSERT_EQ(int64_t(m.vertex_count()), 6 * 256 + 2);
  const float sea = float(planet.sea_height());
  int below = 0;
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const auto p = m.vertex(v);
    double s, t;
    const int f = face_of_direction(p[0], p[1], p[2], &s, &t);
    const int32_t i = int32_t(std::lround((s + 1) * 8)), j = int32_t(std::lround((t + 1) * 8));
    ASSERT_EQ(bits(heights[v]), bits(faces[size_t(f)].at(i, j))) << v;
    below += heights[v] == sea;
  }
  // 1538 vertices on unequal areas (corners' cells are 5 times smaller): a loose check.
  EXPECT_NEAR(double(below) / double(m.vertex_count()), 0.6, 0.1);
  EXPECT_THROW(planet.height(0, 0, 1), Error);
  // The equirect map of 8 x 4 pixels: the sampler's level is 2 at least.
  const Heightfield map = equirect(planet, 64, 32);
  EXPECT_GE(map.stats().min, sea);
  EXPECT_EQ(map.stats().min, sea);
}

TEST(PlanetMidpoint, RefusesWhatItCannotDo) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const Planet planet(midpoint(1));
  EXPECT_NE(message([&] { planet.height(1, 0, 0); }).find("cube-sphere samples"), std::string::npos);
  EXPECT_NE(message([&] { face_patch(planet, 27, 0, 0, 0, 4, 4); }).find("level must be"), std::string::npos);
  EXPECT_NE(message([&] { face_patch(planet, 5, 0, 30, 0, 4, 4); }).find("lies outside face 0"), std::string::npos);
  // A whole face at level 14 (16385^2 floats plus the doubles of two
  // levels, 5.6 GiB) past a 1 GiB cap: refused before allocating.
  set_memory_cap(uint64_t(1) << 30);
  const std::string m = message([&] { face_patch(planet, 14, 0, 0, 0, 16385, 16385); });
  const std::string e = message([&] { equirect(planet, 65536, 32768); });
  set_memory_cap(0);
  EXPECT_NE(m.find("GiB"), std::string::npos) << m;
  EXPECT_NE(e.find("GiB"), std::string::npos) << e;
  PlanetConfig c = midpoint(1);
  c.method = 2;
  EXPECT_NE(message([&] { Planet p(c); }).find("method"), std::string::npos);
}

}  // namespace
}  // namespace ft::planet
