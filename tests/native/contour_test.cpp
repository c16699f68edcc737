// SPDX-License-Identifier: GPL-3.0-or-later
// The contour layer: marching-squares level sets (coastlines), their
// geometry, topology and orientation, bad input, and the coastline CLI.
#include <gtest/gtest.h>
#include <omp.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include <unistd.h>

#include "analysis/box_counting.hpp"
#include "analysis/quantile.hpp"
#include "contour/marching_squares.hpp"
#include "contour/ribbon_clip.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/polyline_io.hpp"
#include "terrain/terrain.hpp"

namespace ft {
namespace {

template <class F>
Heightfield field(int w, int h, F f) {
  Heightfield hf(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) hf.at(x, y) = float(f(double(x), double(y)));
  return hf;
}

double bump(double x, double y, double cx, double cy, double r) {
  return std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (r * r));
}

Heightfield terrain(int levels, double hurst, uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.levels = levels, p.hurst = hurst, p.seed = seed;
  return terrain::generate_terrain(p);
}

int count_kind(const PolylineSet& s, contour::ChainKind k) {
  int n = 0;
  for (int64_t i = 0; i < s.line_count(); ++i) n += contour::chain_kind(s, i) == k;
  return n;
}

double length(const PolylineSet& s, int64_t i) {
  double l = 0;
  for (int64_t k = s.line_begin(i); k + 1 < s.line_end(i); ++k)
    l += std::hypot(s.points[size_t(k + 1)][0] - s.points[size_t(k)][0],
                    s.points[size_t(k + 1)][1] - s.points[size_t(k)][1]);
  return l;
}

TEST(MarchingSquares, EveryVertexLiesOnTheLevelByInterpolation) {
  // Each vertex sits on a grid edge (x or y integral) where the linear
  // interpolation of the edge's two samples equals the level. The samples are
  // floats and t is computed in double, so the residual is rounding of
  // a + t (b - a): a few ulps of the heights, far below 1e-6 of the range.
  const Heightfield hf = terrain(8, 0.6, 5);
  const double level = analysis::heightfield_quantile(hf, 0.4);
  const PolylineSet s = contour::marching_squares(hf, level);
  ASSERT_GT(s.vertex_count(), 1000);
  const HeightStats st = hf.stats();
  for (const Vec3& p : s.points) {
    ASSERT_EQ(p[2], level);
    const double fx = std::floor(p[0]), fy = std::floor(p[1]);
    const bool on_x = fx == p[0], on_y = fy == p[1];
    ASSERT_TRUE(on_x || on_y) << p[0] << " " << p[1];
    double v;
    if (on_y) {  // on a horizontal edge (x, y) - (x + 1, y) (or on a sample)
      const int x = int(fx), y = int(fy);
      const double a = hf.at(x, y), b = x + 1 < hf.width() ? hf.at(x + 1, y) : a;
      v = a + (p[0] - fx) * (b - a);
    } else {
      const int x = int(fx), y = int(fy);
      const double a = hf.at(x, y), b = hf.at(x, y + 1);
      v = a + (p[1] - fy) * (b - a);
    }
    ASSERT_NEAR(v, level, 1e-6 * (st.max - st.min)) << p[0] << " " << p[1];
  }
}

TEST(MarchingSquares, OneBumpIsOneCounterClockwiseIslandOfTheRightSize) {
  // exp(-r^2 / 12^2) = 0.5 at r = 12 sqrt(ln 2) = 9.99: a closed loop of
  // length 2 pi r = 62.8; the inscribed polygon of chords through ~40 cells
  // is shorter by < 0.5%, bilinear interpolation adds < 1%.
  const Heightfield hf = field(64, 64, [](double x, double y) { return bump(x, y, 31.5, 30.2, 12); });
  const PolylineSet s = contour::marching_squares(hf, 0.5);
  ASSERT_EQ(s.line_count(), 1);
  EXPECT_EQ(contour::chain_kind(s, 0), contour::ChainKind::kIsland);
  EXPECT_EQ(s.points.front(), s.points.back());  // closed: first vertex repeated
  const double r = 12 * std::sqrt(std::log(2.0));
  EXPECT_NEAR(length(s, 0), 2 * M_PI * r, 0.015 * 2 * M_PI * r);
  EXPECT_NEAR(contour::signed_area(s, 0), M_PI * r * r, 0.02 * M_PI * r * r);
}

TEST(MarchingSquares, FourBumpsAreFourIslandsAndAPitIsALake) {
  const Heightfield four = field(80, 80, [](double x, double y) {
    return bump(x, y, 20, 20, 6) + bump(x, y, 60, 20, 6) + bump(x, y, 20, 60, 6) + bump(x, y, 60, 60, 6);
  });
  const PolylineSet s = contour::marching_squares(four, 0.5);
  EXPECT_EQ(s.line_count(), 4);
  EXPECT_EQ(count_kind(s, contour::ChainKind::kIsland), 4);
  // The same field upside down: four lakes, land all around them.
  const Heightfield pits = field(80, 80, [&](double x, double y) { return -four.at(int(x), int(y)); });
  const PolylineSet p = contour::marching_squares(pits, -0.5);
  EXPECT_EQ(p.line_count(), 4);
  EXPECT_EQ(count_kind(p, contour::ChainKind::kLake), 4);
  for (int64_t i = 0; i < 4; ++i) EXPECT_NEAR(contour::signed_area(p, i), -contour::signed_area(s, i), 1e-9);
}

TEST(MarchingSquares, SaddlesFollowTheCellMean) {
  // Two peaks touching diagonally: the saddle cell (1,1)-(2,2) has corners
  // 1, 0, 1, 0, mean 0.5. Below the mean the peaks join into one island;
  // above it they are two.
  Heightfield hf(4, 4);
  std::fill(hf.data(), hf.data() + hf.size(), 0.0f);
  hf.at(1, 1) = 1, hf.at(2, 2) = 1;
  EXPECT_EQ(contour::marching_squares(hf, 0.4).line_count(), 1);
  EXPECT_EQ(contour::marching_squares(hf, 0.6).line_count(), 2);
  EXPECT_EQ(count_kind(contour::marching_squares(hf, 0.6), contour::ChainKind::kIsland), 2);
}

TEST(MarchingSquares, ChainsCloseInsideAndEndOnTheBorder) {
  const Heightfield hf = terrain(8, 0.5, 9);
  const PolylineSet s = contour::marching_squares(hf, analysis::heightfield_quantile(hf, 0.5));
  const double w = hf.width() - 1, h = hf.height() - 1;
  auto on_border = [&](const Vec3& p) { return p[0] == 0 || p[1] == 0 || p[0] == w || p[1] == h; };
  int open = 0, closed = 0;
  for (int64_t i = 0; i < s.line_count(); ++i) {
    const Vec3 &a = s.points[size_t(s.line_begin(i))], &b = s.points[size_t(s.line_end(i) - 1)];
    if (a == b) {
      ++closed;
      EXPECT_GE(s.line_end(i) - s.line_begin(i), 4);
    } else {
      ++open;
      EXPECT_TRUE(on_border(a) && on_border(b)) << "chain " << i;
    }
  }
  EXPECT_GT(open, 0);
  EXPECT_GT(closed, 10);
}

TEST(MarchingSquares, OutputDoesNotDependOnThreadCount) {
  const Heightfield hf = terrain(9, 0.5, 2);
  omp_set_num_threads(1);
  const PolylineSet a = contour::marching_squares(hf, 0.1);
  omp_set_num_threads(3);
  const PolylineSet b = contour::marching_squares(hf, 0.1);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.offsets, b.offsets);
}

TEST(MarchingSquares, SamplesExactlyOnTheLevelGiveNoRepeatedVertices) {
  // A quantile level equals a sample; an integer ramp puts whole rows on it.
  const Heightfield hf = field(9, 9, [](double x, double y) { return std::round(x + 0.3 * y); });
  const PolylineSet s = contour::marching_squares(hf, 4.0);
  ASSERT_GT(s.line_count(), 0);
  for (int64_t i = 0; i < s.line_count(); ++i)
    for (int64_t k = s.line_begin(i); k + 1 < s.line_end(i); ++k)
      EXPECT_NE(s.points[size_t(k)], s.points[size_t(k + 1)]);
}

TEST(MarchingSquares, LevelOutsideTheDataOrConstantFieldIsEmptyNaNIsAnError) {
  const Heightfield hf = terrain(6, 0.5, 1);
  const HeightStats st = hf.stats();
  EXPECT_EQ(contour::marching_squares(hf, st.max + 1).line_count(), 0);
  EXPECT_EQ(contour::marching_squares(hf, st.min - 1).line_count(), 0);
  Heightfield flat(10, 10);
  std::fill(flat.data(), flat.data() + flat.size(), 3.0f);
  EXPECT_EQ(contour::marching_squares(flat, 3.0).line_count(), 0);
  EXPECT_EQ(contour::marching_squares(flat, 2.0).line_count(), 0);
  Heightfield holes = terrain(5, 0.5, 1);
  holes.at(4, 7) = NAN;
  try {
    contour::marching_squares(holes, 0.0);
    FAIL() << "NaN accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(e.what()).find("x 4, y 7"), std::string::npos) << e.what();
  }
  EXPECT_THROW(contour::marching_squares(hf, NAN), Error);
  EXPECT_THROW(contour::marching_squares(Heightfield(1, 5), 0.0), Error);
}

// ------------------------------------------------ coastline dimension D = 2 - H

// Box sizes for coastlines of sampled terrains: from 4 cells (below that the
// marching-squares chords straighten the curve and N(eps) tends to 1/eps) up
// to the box counter's default E / 4.
analysis::BoxCountOptions coastline_boxes() {
  analysis::BoxCountOptions o;
  o.min_size = 4;
  return o;
}

PolylineSet one_line(const std::vector<Vec3>& pts, double r) {
  PolylineSet s;
  for (const Vec3& p : pts) s.add(p, r);
  s.end_line();
  return s;
}

void add_ring(PolylineSet& rings, const std::vector<std::array<double, 2>>& xy) {
  for (const auto& [x, y] : xy) rings.add({x, y, 0.0});
  rings.end_line();
}

TEST(RibbonClip, ALineAcrossALakeEndsWhereItsRibbonReachesTheShore) {
  // A river 1 wide (radius 0.5) along y = 0.5 through a square lake [4, 6] x [2, 3]
  // whose near corner lies 1.5 off the line: its ribbon (|y - 0.5| <= 0.5) misses it;
  // through [4, 6] x [0.8, 3] it is cut from x = 4 to 6 (the ribbon's flat end
  // square to the flow reaches the shore there, its centre 0.3 off the water).
  PolylineSet lake;
  add_ring(lake, {{4, 2}, {6, 2}, {6, 3}, {4, 3}});
  const PolylineSet line = one_line({{0, 0.5, 1.0}, {10, 0.5, 0.0}}, 0.5);
  const PolylineSet missed = contour::clip_ribbons(line, lake, 0.3);
  ASSERT_EQ(missed.line_count(), 1);
  EXPECT_EQ(missed.points, line.points);
  PolylineSet near;
  add_ring(near, {{4, 0.8}, {6, 0.8}, {6, 3}, {4, 3}});
  const PolylineSet cut = contour::clip_ribbons(line, near, 0.3);
  // The line falls 1 over 10: its cross-section leans along it, its top 0.3 r
  // sin(slope) ahead, so the cut comes that much sooner (and later past the lake).
  const double lean = 0.3 * 0.5 / std::sqrt(101.0);
  ASSERT_EQ(cut.line_count(), 2);
  ASSERT_EQ(cut.vertex_count(), 4);
  EXPECT_NEAR(cut.points[1][0], 4.0 - lean, 1e-12);
  EXPECT_NEAR(cut.points[1][2], 1.0 - (4.0 - lean) / 10, 1e-12);  // z interpolated
  EXPECT_NEAR(cut.points[2][0], 6.0 + lean, 1e-12);
  EXPECT_EQ(cut.points[3], line.points[1]);
  EXPECT_EQ(cut.radii, std::vector<double>(4, 0.5));
}

TEST(RibbonClip, AnObliqueShoreCutsWhereTheRibbonsCornerTouchesAndIslandsAreDry) {
  // The shore x + y = 6 (the lake beyond it): the ribbon's cross-section at x reaches
  // y = 1 at its upper corner, so it ends at x = 5 (its centre 0.5 from the shore
  // along the flow, 0.35 across it).
  PolylineSet lake;
  add_ring(lake, {{6, 0}, {20, 0}, {20, 20}, {-14, 20}});
  const PolylineSet cut = contour::clip_ribbons(one_line({{0, 0.5, 0}, {10, 0.5, 0}}, 0.5), lake, 0.3);
  ASSERT_EQ(cut.line_count(), 1);
  EXPECT_NEAR(cut.points.back()[0], 5.0, 1e-12);
  // An island [2, 8] x [-3, 3] in a lake [-10, 20] x [-10, 10]: the ribbon runs on
  // the island from shore to shore, x in [2, 8], and nowhere else.
  PolylineSet rings;
  add_ring(rings, {{-10, -10}, {20, -10}, {20, 10}, {-10, 10}});
  add_ring(rings, {{2, -3}, {8, -3}, {8, 3}, {2, 3}});
  const PolylineSet island = contour::clip_ribbons(one_line({{0, 0, 0}, {10, 0, 0}}, 0.5), rings, 0.3);
  ASSERT_EQ(island.line_count(), 1);
  EXPECT_NEAR(island.points.front()[0], 2.0, 1e-12);
  EXPECT_NEAR(island.points.back()[0], 8.0, 1e-12);
  // Where a line turns, its ribbon sweeps a disc of its radius about the point: the
  // turn at (5, 2) under a shore at y = 2.48 ends a part there (the disc reaches
  // y = 2.5), though each edge's own band stays dry (up to y = 2.464).
  PolylineSet shore;
  add_ring(shore, {{-10, 2.48}, {20, 2.48}, {20, 10}, {-10, 10}});
  const PolylineSet turn = contour::clip_ribbons(one_line({{0, 0, 0}, {5, 2, 0}, {10, 0, 0}}, 0.5), shore, 0.3);
  ASSERT_EQ(turn.line_count(), 2);
  EXPECT_EQ(turn.vertex_count(), 4);
  EXPECT_EQ(turn.points[1], (Vec3{5, 2, 0}));
  EXPECT_EQ(turn.points[2], (Vec3{5, 2, 0}));
}

TEST(CoastlineDimension, MedianLevelSetOfMidpointTerrainsHasDimensionTwoMinusH) {
  // Feder 13.4 (seed 001): a horizontal section of a self-affine surface is a
  // self-similar curve of dimension 2 - H. Ten 1025^2 midpoint terrains per H
  // (seeds 1..10), median level, boxes 4..256 cells. Measured: the spread of
  // single terrains is sd 0.045, so the mean of ten has sd 0.014; the mean's
  // offset from 2 - H is -0.025 (H = 0.5: the coarsest sampled scales still
  // curve) and +0.017 (H = 0.8). The bound 0.06 leaves 2.5 sd
  // beyond that offset.
  for (double h : {0.5, 0.8}) {
    std::vector<double> d(10);
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < 10; ++k) {
      ft_terrain_params p = terrain::default_terrain_params();
      p.levels = 10, p.hurst = h, p.seed = uint64_t(k + 1), p.threads = 1;
      const Heightfield hf = terrain::generate_terrain(p);
      const PolylineSet s = contour::marching_squares(hf, analysis::heightfield_quantile(hf, 0.5));
      d[size_t(k)] = analysis::box_counting_dimension(s, coastline_boxes()).dimension;
    }
    double mean = 0;
    for (double v : d) mean += v / 10;
    EXPECT_NEAR(mean, 2 - h, 0.06) << "H " << h;
  }
}

TEST(CoastlineDimension, ContourOfAConeIsACircleAndOfARampALineOfDimensionOne) {
  // Known curves through the coastline path: a level set of a cone is a
  // circle of radius 200 cells, of a tilted plane a straight line; both have
  // D = 1. A smooth curve covers N = L / eps + O(1) boxes, so the slope
  // tends to 1 only for boxes well below its size: boxes 1..25 cells (1.016
  // measured for the circle; 1.04 at 1..100, 1.07 at 4..100).
  analysis::BoxCountOptions small;
  small.min_size = 1, small.max_size = 25;
  const Heightfield cone = field(513, 513, [](double x, double y) { return std::hypot(x - 256.3, y - 255.8); });
  const PolylineSet circle = contour::marching_squares(cone, 200);
  ASSERT_EQ(circle.line_count(), 1);
  EXPECT_EQ(contour::chain_kind(circle, 0), contour::ChainKind::kLake);  // land (higher) outside
  EXPECT_NEAR(analysis::box_counting_dimension(circle, small).dimension, 1.0, 0.03);
  const Heightfield ramp = field(513, 513, [](double x, double y) { return 0.3 * x + 0.7 * y; });
  const PolylineSet line = contour::marching_squares(ramp, 180);
  ASSERT_EQ(line.line_count(), 1);
  EXPECT_EQ(contour::chain_kind(line, 0), contour::ChainKind::kOpen);
  EXPECT_NEAR(analysis::box_counting_dimension(line, small).dimension, 1.0, 0.03);
}

// ---------------------------------------------------------------------- CLI

int run_cli(const std::string& args, std::string* out = nullptr) {
  FILE* p = popen((std::string(FT_CLI_PATH) + " " + args + " 2>&1").c_str(), "r");
  std::string s;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) s.append(buf, n);
  if (out) *out = s;
  return WEXITSTATUS(pclose(p));
}

TEST(CoastlineCli, WritesPolylinesAndCountsIslandsAndLakes) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_coastline_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string t = (dir / "t.npy").string(), csv = (dir / "c.csv").string(), png = (dir / "p.png").string();
  io::write_heightfield(terrain(8, 0.7, 4), t);
  std::string out;
  ASSERT_EQ(run_cli("coastline --in " + t + " --level q0.5 --out " + csv + " --preview " + png, &out), 0) << out;
  const nlohmann::json j = nlohmann::json::parse(out);
  const PolylineSet s = io::read_polylines(csv);
  EXPECT_EQ(j["chains"].get<int64_t>(), s.line_count());
  EXPECT_EQ(j["islands"].get<int>() + j["lakes"].get<int>() + j["open_chains"].get<int>(), s.line_count());
  EXPECT_EQ(j["islands"].get<int>(), count_kind(s, contour::ChainKind::kIsland));
  EXPECT_TRUE(std::filesystem::exists(png));
  // The coastline file read back by analyze: a curve, D by box counting.
  ASSERT_EQ(run_cli("analyze " + csv, &out), 0) << out;
  const nlohmann::json a = nlohmann::json::parse(out);
  EXPECT_EQ(a["kind"], "polylines");
  EXPECT_EQ(a["recommended"], "box_counting");
  EXPECT_GT(a["dimension"].get<double>(), 1.0);
  EXPECT_LT(a["dimension"].get<double>(), 1.6);
  EXPECT_DOUBLE_EQ(a["hurst"].get<double>(), 2 - a["dimension"].get<double>());
  // --world: columns and rows scaled to the recorded world size. A .npy of
  // another program has no sidecar (<file>.npy.json), so it records none.
  std::filesystem::remove(t + ".json");
  EXPECT_EQ(run_cli("coastline --in " + t + " --world --out " + csv, &out), 1);  // none recorded
  EXPECT_NE(out.find("world size"), std::string::npos) << out;
  Heightfield sized = terrain(8, 0.7, 4);
  sized.set_world_size(10);
  const std::string wpng = (dir / "w.png").string();  // .png records the world size
  io::write_heightfield(sized, wpng);
  ASSERT_EQ(run_cli("coastline --in " + wpng + " --level q0.5 --out " + csv, &out), 0) << out;
  const PolylineSet g = io::read_polylines(csv);
  ASSERT_EQ(run_cli("coastline --in " + wpng + " --level q0.5 --world --out " + csv, &out), 0) << out;
  const PolylineSet w = io::read_polylines(csv);
  ASSERT_EQ(w.vertex_count(), g.vertex_count());
  for (size_t i = 0; i < w.points.size(); ++i) {
    EXPECT_DOUBLE_EQ(w.points[i][0], g.points[i][0] * (10.0 / 256));
    EXPECT_DOUBLE_EQ(w.points[i][1], g.points[i][1] * (10.0 / 256));
  }
  EXPECT_EQ(run_cli("coastline --in " + t + " --level qhalf --out " + csv, &out), 1);
  EXPECT_NE(out.find("--level"), std::string::npos) << out;
  EXPECT_EQ(run_cli("coastline --in " + (dir / "none.npy").string() + " --out " + csv, &out), 1);
  std::filesystem::remove_all(dir);
}

TEST(CoastlineCli, ALevelOutsideTheHeightsIsAClearErrorAndWritesNothing) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_coastline_level_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string t = (dir / "t.npy").string(), csv = (dir / "c.csv").string();
  const Heightfield hf = terrain(6, 0.7, 4);
  io::write_heightfield(hf, t);
  const HeightStats s = hf.stats();
  std::string out;
  for (double level : {s.max + 1, s.min - 1, 1e6}) {
    char arg[64];
    std::snprintf(arg, sizeof arg, "%.9g", level);
    EXPECT_EQ(run_cli("coastline --in " + t + " --level " + arg + " --out " + csv, &out), 1) << level;
    EXPECT_NE(out.find("outside the heights"), std::string::npos) << out;
    EXPECT_NE(out.find("q0.5"), std::string::npos) << out;  // says what to do instead
    EXPECT_FALSE(std::filesystem::exists(csv));
  }
  std::filesystem::remove_all(dir);
}

// Every terrain method records its world size, so `coastline --world` works
// on all of them (it used to fail with "records no world size" for fbm,
// spectral and interpolated).
TEST(CoastlineCli, WorldUnitsFromTerrainsOfEveryMethod) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_coastline_world_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string t = (dir / "t.png").string(), csv = (dir / "c.csv").string();
  for (const char* method : {"fbm", "spectral", "interpolated", "midpoint"}) {
    std::string out;
    const std::string size = std::string(method) == "midpoint" ? " --levels 7" : " --size 129";
    ASSERT_EQ(run_cli(std::string("terrain --method ") + method + size + " --world-size 40 --out " + t, &out), 0)
        << out;
    ASSERT_EQ(run_cli("coastline --in " + t + " --world --out " + csv, &out), 0) << method << ": " << out;
    const PolylineSet w = io::read_polylines(csv);
    ASSERT_GT(w.vertex_count(), 0) << method;
    double hi = 0;
    for (const Vec3& p : w.points) hi = std::max({hi, p[0], p[1]});
    EXPECT_LE(hi, 40.0) << method;
    EXPECT_GT(hi, 20.0) << method;  // columns (up to 128) were scaled by 40 / 128
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ft
