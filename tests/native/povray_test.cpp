// SPDX-License-Identifier: GPL-3.0-or-later
// The POV-Ray writer without povray: SDL numbers, strings, identifiers,
// paths, sweep chunking and camera framing. (Real renders: tests/povray.)
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "povray/camera.hpp"
#include "povray/pov_params.hpp"
#include "povray/river_ribbons.hpp"
#include "povray/scene.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"

namespace ft::pov {
namespace {

TEST(PovSdl, NumbersKeepNineSignificantDigits) {
  EXPECT_EQ(number(0.123456789012), "0.123456789");
  EXPECT_EQ(number(1234567.891), "1234567.89");
  EXPECT_EQ(number(-0.0), "0");
  EXPECT_EQ(number(1e-12), "1e-12");
  EXPECT_EQ(vec({1, 2.5, -3}), "<1, 2.5, -3>");
  EXPECT_THROW(number(NAN), Error);
  EXPECT_THROW(number(INFINITY), Error);
}

TEST(PovSdl, QuotedStringsCannotBreakOut) {
  EXPECT_EQ(quoted("a.png"), "\"a.png\"");
  EXPECT_EQ(quoted("x\" } sphere { 0, 1 } #declare A = \"y"),
            "\"x\\\" } sphere { 0, 1 } #declare A = \\\"y\"");
  EXPECT_THROW(quoted("dir\\file.png"), Error);
  EXPECT_THROW(quoted("a\nb"), Error);
  EXPECT_THROW(quoted(std::string("a\0b", 3)), Error);
}

TEST(PovSdl, IdentifiersMustBeSafeAndCannotBeKeywords) {
  EXPECT_EQ(identifier("Terrain_1", "name"), "Terrain_1");
  EXPECT_THROW(identifier("sphere", "name"), Error);  // no capital: could be a keyword
  EXPECT_THROW(identifier("1Terrain", "name"), Error);
  EXPECT_THROW(identifier("Ter rain", "name"), Error);
  EXPECT_THROW(identifier("A = 1; #debug", "name"), Error);
  EXPECT_THROW(identifier("", "name"), Error);
}

TEST(PovSdl, PathsAreRelativeToTheSceneFolder) {
  EXPECT_EQ(relative_path("/a/b/scene.terrain.png", "/a/b"), "scene.terrain.png");
  EXPECT_EQ(relative_path("/a/img/t.png", "/a/b"), "../img/t.png");
  EXPECT_EQ(folder_of("x.pov"), ".");
  EXPECT_EQ(folder_of("d/x.pov"), "d");
}

PolylineSet line_of(int n) {
  PolylineSet s;
  for (int i = 0; i < n; ++i) s.add({double(i), std::sin(i * 0.3), 0}, 0.01 * (1 + i));
  s.end_line();
  return s;
}

std::vector<int> sweep_sizes(const std::string& sdl, const char* kind) {
  std::vector<int> sizes;
  std::regex re(std::string(kind) + " (\\d+),");
  for (std::sregex_iterator it(sdl.begin(), sdl.end(), re), end; it != end; ++it) sizes.push_back(std::stoi((*it)[1]));
  return sizes;
}

TEST(PovSweep, LinearPiecesShareEndPointsAndCoverTheLine) {
  SweepOptions o;
  o.segments_per_sweep = 16;
  const std::string sdl = sweeps_sdl(line_of(100), o);  // 99 segments: 6 x 16 + 3
  EXPECT_EQ(sdl.rfind("union {", 0), 0u);
  const auto sizes = sweep_sizes(sdl, "linear_spline");
  ASSERT_EQ(sizes.size(), 7u);
  int segments = 0;
  for (int n : sizes) {
    EXPECT_GE(n, 2);
    segments += n - 1;
  }
  EXPECT_EQ(segments, 99);
  // The last point of one piece is the first of the next.
  EXPECT_NE(sdl.find("<16, 0, -0.996164609>, 0.17\n}\nsphere_sweep { linear_spline 17,\n  <16, 0, -0.996164609>, 0.17"),
            std::string::npos)
      << sdl.substr(0, 2000);
}

TEST(PovSweep, CubicPiecesHaveFourPointsAndTolerance) {
  SweepOptions o;
  o.spline = SweepSpline::kCubic;
  o.segments_per_sweep = 16;
  const std::string sdl = sweeps_sdl(line_of(18), o);  // 17 segments: 16 + 1
  const auto sizes = sweep_sizes(sdl, "cubic_spline");
  ASSERT_EQ(sizes.size(), 2u);
  EXPECT_EQ(sizes[0], 19);
  EXPECT_EQ(sizes[1], 4);  // one segment plus its two control points
  EXPECT_NE(sdl.find("tolerance 0.001"), std::string::npos);
  // The first control point mirrors point 1 about point 0: world
  // (-1, -sin(0.3), 0), written in POV axes.
  EXPECT_NE(sdl.find("<-1, 0, -0.295520207>"), std::string::npos);
}

TEST(PovSweep, RepeatedPointsAreDroppedAndLonePointsBecomeSpheres) {
  PolylineSet s;
  for (double x : {0.0, 0.0, 1.0, 1.0 + 1e-12, 2.0}) s.add({x, 0, 0});
  s.end_line();
  s.add({5, 5, 5});
  s.add({5, 5, 5});
  s.end_line();
  SweepStats st;
  SweepOptions o;
  const std::string sdl = sweeps_sdl(s, o, "", &st);
  EXPECT_EQ(st.duplicates_removed, 3);
  EXPECT_EQ(st.sweeps, 1);
  EXPECT_EQ(st.spheres, 1);
  EXPECT_EQ(sweep_sizes(sdl, "linear_spline"), std::vector<int>{3});
  // Radius 0 takes the default radius; POV axes swap y and z.
  EXPECT_NE(sdl.find("sphere { <5, 5, 5>, 0.01 }"), std::string::npos) << sdl;
}

TEST(PovSweep, RejectsBadOptionsAndRadii) {
  SweepOptions o;
  o.segments_per_sweep = 0;
  EXPECT_THROW(sweeps_sdl(line_of(3), o), Error);
  o = {};
  o.default_radius = 0;
  EXPECT_THROW(sweeps_sdl(line_of(3), o), Error);
  PolylineSet s = line_of(3);
  s.radii[1] = -1;
  EXPECT_THROW(sweeps_sdl(s, {}), Error);
  s.radii[1] = NAN;
  EXPECT_THROW(sweeps_sdl(s, {}), Error);
}

TEST(PovCamera, FramedPointsAllLandInsideTheImage) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 50; ++i) pts.push_back({std::cos(i * 1.3) * 3, std::abs(std::sin(i * 0.7)), std::sin(i * 2.1) * 2});
  for (double az : {0.0, 90.0, 200.0, -45.0})
    for (double el : {10.0, 45.0, 90.0}) {
      CameraOptions o;
      o.azimuth_deg = az;
      o.elevation_deg = el;
      const Camera c = frame_points(pts, o);
      double umin = 1, umax = 0, vmin = 1, vmax = 0;
      for (const Vec3& p : pts) {
        double u, v;
        ASSERT_TRUE(c.project(p, u, v));
        umin = std::min(umin, u), umax = std::max(umax, u), vmin = std::min(vmin, v), vmax = std::max(vmax, v);
      }
      EXPECT_GT(umin, 0) << az << " " << el;
      EXPECT_LT(umax, 1);
      EXPECT_GT(vmin, 0);
      EXPECT_LT(vmax, 1);
      // Tight: some point touches the margin (2% of the frame) on some side.
      EXPECT_LT(std::min({umin, 1 - umax, vmin, 1 - vmax}), 0.03) << az << " " << el;
    }
}

// Every settings row of the scene and sweep tables reaches the exporter's
// types, converted: a row added to a table without its binding fails here.
TEST(PovParams, EverySettingsRowIsBoundAndCarriedOver) {
  EXPECT_EQ(unbound_rows(scene_param_table(), scene_bindings()), std::vector<std::string>{});
  EXPECT_EQ(unbound_rows(sweep_param_table(), sweep_bindings()), std::vector<std::string>{});
  ft_pov_scene_params c = defaults_of<ft_pov_scene_params>(scene_param_table());
  c.has_sea = 1, c.sea_level = -0.25, c.camera_azimuth_deg = 33, c.camera_center_v = 0.6, c.camera_given = 1;
  c.camera_up[2] = 0.75, c.sun_color[1] = 2.5;
  SceneParams s;
  apply_scene_settings(c, s);
  EXPECT_TRUE(s.has_sea);
  EXPECT_EQ(s.sea_level, -0.25);
  EXPECT_EQ(s.camera.azimuth_deg, 33);
  EXPECT_EQ(s.camera.center_v, 0.6);
  EXPECT_TRUE(s.camera_given);
  EXPECT_EQ(s.camera_pose.up, (Vec3{0, 0, 0.75}));
  EXPECT_EQ(s.sun_color, (Vec3{1, 2.5, 1}));
  ft_pov_sweep_params w = defaults_of<ft_pov_sweep_params>(sweep_param_table());
  w.spline = FT_POV_SWEEP_CUBIC, w.segments_per_sweep = 17;
  const SweepOptions o = sweep_options(w);
  EXPECT_EQ(o.spline, SweepSpline::kCubic);
  EXPECT_EQ(o.segments_per_sweep, 17);
  c.camera_center_v = 0.9;  // the table's range is checked first
  EXPECT_THROW(apply_scene_settings(c, s), Error);
}

TEST(PovScene, RejectsBadParametersBeforeWritingAnything) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_pov_unit_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Heightfield hf(5, 5);
  for (size_t i = 0; i < hf.size(); ++i) hf.data()[i] = float(i);
  SceneParams p;
  p.terrain = &hf;
  p.world_size_x = -1;
  EXPECT_THROW(write_scene(p, (dir / "a.pov").string()), Error);
  p.world_size_x = 1;
  // The camera's ranges are the table's, checked where settings enter
  // (apply_scene_settings; PovCapi.CameraMarginAndCentreAreSettingsOfTheTable).
  p.has_sea = true;
  p.sea_level = NAN;
  EXPECT_THROW(write_scene(p, (dir / "a.pov").string()), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

// `fracterra terrain --pov` places the terrain in its recorded world units,
// heights unscaled; it used to ignore the world size (always 1 wide).
TEST(PovScene, TerrainSceneUsesTheRecordedWorldSize) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_pov_world_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Heightfield hf(33, 17);
  for (size_t i = 0; i < hf.size(); ++i) hf.data()[i] = float(std::sin(double(i)));
  hf.set_world_size(40);
  SceneSummary sum = write_terrain_scene(hf, (dir / "w.pov").string());
  EXPECT_DOUBLE_EQ(sum.terrain.world_size_x, 40);
  EXPECT_DOUBLE_EQ(sum.terrain.world_size_y, 20);  // 40 * 16 / 32
  EXPECT_DOUBLE_EQ(sum.terrain.vertical_scale, 1);
  EXPECT_NEAR(sum.hi[0] - sum.lo[0], 40, 1e-9);
  hf.set_world_size(0);  // none recorded: 1 wide, relief 20% of that
  sum = write_terrain_scene(hf, (dir / "n.pov").string());
  EXPECT_DOUBLE_EQ(sum.terrain.world_size_x, 1);
  std::filesystem::remove_all(dir);
}

// The radii written for the sweeps of a scene, in file order.
std::vector<double> sweep_radii(const std::string& sdl) {
  std::vector<double> r;
  static const std::regex point(R"(\n  <[^>]*>, ([-+0-9.e]+)(?=\n))");
  for (auto it = std::sregex_iterator(sdl.begin(), sdl.end(), point); it != std::sregex_iterator(); ++it)
    r.push_back(std::stod((*it)[1]));
  return r;
}

// A fractal line of 2^14 + 1 points across the unit square.
PolylineSet fine_line() {
  PolylineSet s;
  const int n = 16384;
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    s.add({t, 0.5 + 0.05 * std::sin(t * 97) + 0.01 * std::sin(t * 2113), 0}, 0.01);  // the CSV's radius
  }
  s.end_line();
  return s;
}

TEST(PovScene, AutomaticRadiusIsThreeQuartersOfAPixelOnFineLines) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_pov_radius_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const PolylineSet line = fine_line();
  SceneLines l{&line, LineKind::kGeneric};
  l.radii_in_world_units = false;
  const std::string f = (dir / "fine.pov").string();
  const SceneSummary sum = write_polyline_scene(l, f, polyline_camera(), 800);
  // The pixel footprint at the line's box centre, computed here again.
  const Vec3 c{(sum.lo[0] + sum.hi[0]) / 2, (sum.lo[1] + sum.hi[1]) / 2, (sum.lo[2] + sum.hi[2]) / 2};
  const Vec3& e = sum.camera.location;
  const double d = std::hypot(c[0] - e[0], c[1] - e[1], c[2] - e[2]);
  const double pixel = 2 * d * std::tan(sum.camera.fov_deg * M_PI / 360) / 800;
  const std::vector<double> r = sweep_radii(io::read_file(f));
  ASSERT_EQ(r.size(), line.points.size() + 16384 / 32 - 1);  // pieces of 32 segments share their ends
  for (double x : r) EXPECT_NEAR(x, 0.75 * pixel, 1e-6 * pixel);
  EXPECT_LT(r[0], 0.01 / 5);  // the CSV's 0.01 was a worm 7 pixels wide
  // Twice the width in pixels: half the radius.
  write_polyline_scene(l, f, polyline_camera(), 1600);
  EXPECT_NEAR(sweep_radii(io::read_file(f))[0], 0.375 * pixel, 1e-6 * pixel);
  std::filesystem::remove_all(dir);
}

TEST(PovScene, RadiusOverridesScaleAndTaperOrTheFileRadii) {
  const auto dir = std::filesystem::temp_directory_path() / ("ft_pov_taper_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  PolylineSet s;  // a main line (radius 0.02) and a branch (0.01)
  s.add({0, 0, 0}, 0.02), s.add({1, 0.2, 0}, 0.02), s.end_line();
  s.add({0.5, 0.1, 0}, 0.01), s.add({0.7, 0.5, 0}, 0.01), s.end_line();
  const std::string f = (dir / "t.pov").string();
  SceneLines l{&s, LineKind::kGeneric, 0.004};
  l.radii_in_world_units = false;  // the file's radii as taper
  write_polyline_scene(l, f, polyline_camera());
  EXPECT_EQ(sweep_radii(io::read_file(f)), (std::vector<double>{0.004, 0.004, 0.002, 0.002}));
  l.radius_scale = 2.5;
  write_polyline_scene(l, f, polyline_camera());
  EXPECT_EQ(sweep_radii(io::read_file(f)), (std::vector<double>{0.01, 0.01, 0.005, 0.005}));
  l.radii_in_world_units = true;  // the file's radii as they are (the C ABI's rule)
  l.radius_scale = 1;
  write_polyline_scene(l, f, polyline_camera());
  EXPECT_EQ(sweep_radii(io::read_file(f)), (std::vector<double>{0.02, 0.02, 0.01, 0.01}));
  std::filesystem::remove_all(dir);
}


// --- Rivers as ribbons in their beds -------------------------------------

// A river down a slope s = 1 (45 degrees), half a unit wide, then level
// and turning: the ribbon Blender's river curve is (flat ellipse, Z-up).
PolylineSet steep_then_level_river() {
  PolylineSet rivers;
  rivers.add({0, 0, 2}, 0.25);
  rivers.add({1, 0, 1}, 0.25);
  rivers.add({1, 0, 1}, 0.25);  // a repeated point: skipped
  rivers.add({2, 0, 0}, 0.25);
  rivers.add({3, 0, 0}, 0.0);   // no radius: the default
  rivers.add({3, 1, 0}, 0.25);
  rivers.end_line();
  rivers.add({5, 5, 5}, 0.25);  // one point: no ribbon
  rivers.end_line();
  return rivers;
}

TEST(RiverRibbons, EachRingIsTheFlatEllipseSquareToTheFlow) {
  // Every ring vertex lies in the plane square to the flow's direction at
  // its point (the mean of the two segments'), the radius across and flat
  // x the radius along that plane's upward axis (its top vertex flat r
  // cos(dip) above the point): on the 45-degree stretch the ribbon's
  // surface then stands flat r / cos(dip) = 0.106 over its centreline. A
  // sphere_sweep squashed vertically by 0.3 stood r sqrt(0.09 + 1) = 0.26
  // over it there, most of the river's width.
  const double flat = 0.3, r = 0.25, fallback = 0.1;
  const int sides = 8;
  const Mesh m = river_ribbons(steep_then_level_river(), flat, sides, fallback);
  const Vec3 centre[] = {{0, 0, 2}, {1, 0, 1}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}};
  const double radius[] = {r, r, r, fallback, r};
  const double s = std::sqrt(0.5);
  const Vec3 flow[] = {{s, 0, -s}, {s, 0, -s}, {0, 0, 0}, {s, s, 0}, {0, 1, 0}};
  ASSERT_EQ(m.vertex_count(), size_t(5 * sides));
  for (int i = 0; i < 5; ++i) {
    Vec3 t = flow[i];
    if (i == 2) {  // between the 45-degree stretch and the level one
      const double a = std::sqrt(0.5), len = std::sqrt((a + 1) * (a + 1) + a * a);
      t = {(a + 1) / len, 0, -a / len};
    }
    double widest = 0, highest = 0;
    for (int k = 0; k < sides; ++k) {
      const auto v = m.vertex(size_t(i * sides + k));
      const Vec3 d{v[0] - centre[i][0], v[1] - centre[i][1], v[2] - centre[i][2]};
      EXPECT_NEAR(d[0] * t[0] + d[1] * t[1] + d[2] * t[2], 0.0, 1e-6) << "ring " << i << " vertex " << k;
      // The level axis across the flow, and the upward one in the ring's plane.
      const double hx = -t[1], hy = t[0], hn = std::hypot(hx, hy);
      const double across = (d[0] * hx + d[1] * hy) / hn;
      const double up = std::sqrt(std::max(0.0, d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - across * across));
      widest = std::max(widest, std::fabs(across));
      highest = std::max(highest, d[2]);
      EXPECT_LE(up, flat * radius[i] + 1e-6) << "ring " << i << " vertex " << k;
    }
    EXPECT_NEAR(widest, radius[i], 1e-6) << "ring " << i;
    const double cos_dip = std::hypot(t[0], t[1]);
    EXPECT_NEAR(highest, flat * radius[i] * cos_dip, 1e-6) << "ring " << i;
  }
}

TEST(RiverRibbons, AreClosedAndFaceOutwards) {
  // Every edge is shared by exactly two faces in opposite directions (a
  // closed, consistently oriented surface: its smooth normals do not
  // cancel), and every face's Newell normal points away from the river.
  const Mesh m = river_ribbons(steep_then_level_river(), 0.3, 8, 0.1);
  std::map<std::pair<int32_t, int32_t>, int> directed;
  size_t first = 0;
  for (int32_t n : m.face_sizes) {
    for (int32_t k = 0; k < n; ++k) ++directed[{m.face_indices[first + k], m.face_indices[first + (k + 1) % n]}];
    first += size_t(n);
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
  // Outwards: the normal's direction from the ribbon's centroid of the face's ring points.
  first = 0;
  for (int32_t n : m.face_sizes) {
    const auto area = face_vector_area(m, m.face_indices.data() + first, n);
    std::array<double, 3> c{}, axis{};
    for (int32_t k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) c[size_t(d)] += m.vertex(size_t(m.face_indices[first + k]))[size_t(d)] / n;
    // The nearest point of the river's centreline: the ring centre of the face's first vertex.
    const size_t ring = size_t(m.face_indices[first]) / 8;
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) axis[size_t(d)] += m.vertex(ring * 8 + size_t(k))[size_t(d)] / 8;
    double out = 0;
    for (int d = 0; d < 3; ++d) out += area[size_t(d)] * (c[size_t(d)] - axis[size_t(d)]);
    if (n == 8) {  // an end cap: its centroid is the ring centre; it faces along the flow
      EXPECT_GT(std::fabs(area[0]) + std::fabs(area[1]) + std::fabs(area[2]), 0.0);
    } else {
      EXPECT_GT(out, 0.0) << "face at " << first;
    }
    first += size_t(n);
  }
}

TEST(RiverRibbons, EndCapsFaceUpstreamAndDownstream) {
  PolylineSet one;
  one.add({0, 0, 0}, 1.0);
  one.add({1, 0, 0}, 1.0);
  one.end_line();
  const Mesh m = river_ribbons(one, 0.3, 8, 0.1);
  ASSERT_EQ(m.face_count(), size_t(8 + 2));
  const auto start = face_vector_area(m, m.face_indices.data() + 32, 8);
  const auto end = face_vector_area(m, m.face_indices.data() + 40, 8);
  EXPECT_LT(start[0], 0.0);
  EXPECT_GT(end[0], 0.0);
}

}  // namespace
}  // namespace ft::pov
