// SPDX-License-Identifier: GPL-3.0-or-later
// The POV-Ray layer against the real povray: small renders (160 x 120) of
// written scenes, the examples and the macros; trace() probes for the
// height_field's orientation and heights.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/mesh.hpp"
#include "io/atomic_file.hpp"
#include "io/png_image.hpp"
#include "povray/heightfield_export.hpp"
#include "povray/render.hpp"
#include "povray/scene.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"

namespace fs = std::filesystem;

namespace ft {
namespace {

const std::string kSource = FT_SOURCE_DIR;

// A fresh folder per test, removed afterwards.
class PovTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ft_pov_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Renders with no warnings allowed; returns the luma image.
  GrayImage render(const std::string& scene, int w = 160, int h = 120, double aa = 0,
                   std::string* messages = nullptr) {
    pov::RenderOptions o;
    o.width = w;
    o.height = h;
    o.antialias = aa;
    o.include_paths = {kSource + "/povray_macros"};
    const std::string out = path("render_" + std::to_string(count_++) + ".png");
    const pov::RenderResult r = pov::render_scene(scene, out, o);
    EXPECT_EQ(r.warnings, 0) << "povray warned on " << scene << ":\n" << r.messages;
    if (messages) *messages = r.messages;
    return io::read_png(out);
  }
  fs::path dir_;
  int count_ = 0;
};

struct Stats {
  double mean = 0, sd = 0;
};
Stats pixel_stats(const GrayImage& img) {
  const double full = img.bit_depth == 16 ? 65535.0 : 255.0;
  double s = 0, ss = 0;
  for (uint16_t p : img.pixels) s += p / full, ss += (p / full) * (p / full);
  const double n = double(img.pixels.size());
  return {s / n, std::sqrt(std::max(0.0, ss / n - (s / n) * (s / n)))};
}
double luma(const GrayImage& img, int x, int y) {
  return img.pixels[size_t(y) * img.width + x] / (img.bit_depth == 16 ? 65535.0 : 255.0);
}
// Pixels that stand out from the picture's median grey by more than 0.08:
// a thin line over a plain ground (whose own shading varies by < 0.02).
int64_t standout_pixels(const GrayImage& img) {
  const double full = img.bit_depth == 16 ? 65535.0 : 255.0;
  std::vector<uint16_t> v(img.pixels);
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  const double med = v[v.size() / 2] / full;
  int64_t n = 0;
  for (uint16_t p : img.pixels) n += std::fabs(p / full - med) > 0.08;
  return n;
}
// A rendered picture is "not blank" when its pixels vary: a uniform image has
// sd 0 and even a plain sky gradient has sd < 0.02 at this size.
void expect_not_blank(const GrayImage& img, const std::string& what) {
  const Stats s = pixel_stats(img);
  EXPECT_GT(s.sd, 0.04) << what << " looks blank (mean " << s.mean << ")";
  EXPECT_GT(s.mean, 0.005) << what;
  EXPECT_LT(s.mean, 0.995) << what;
}

// A polyline that wanders (a deterministic, non-random test input).
PolylineSet wiggle(int n, double radius = 0) {
  PolylineSet s;
  for (int i = 0; i < n; ++i) {
    const double t = double(i) / (n - 1);
    s.add({t, 0.25 * std::sin(9 * t) + 0.05 * std::sin(83 * t), 0.1 + 0.05 * std::cos(31 * t)}, radius);
  }
  s.end_line();
  return s;
}

int run_cli(const std::string& args, std::string& output) {
  const std::string cmd = std::string(FT_CLI_PATH) + " " + args + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) output.append(buf, n);
  const int status = ::pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(PovTest, ExampleScenesRenderWithoutWarningsAndAreNotBlank) {
  int found = 0;
  for (const auto& e : fs::directory_iterator(kSource + "/examples")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".pov") continue;
    ++found;
    SCOPED_TRACE(name);
    expect_not_blank(render(e.path().string()), name);
  }
  EXPECT_GE(found, 3);
}

TEST_F(PovTest, TraceProbeConfirmsOrientationAndHeightTo16BitPrecision) {
  // Every sample different and the grid not square: a swapped or mirrored
  // axis, or heights off by the 65535/65536 of POV-Ray's 16-bit reading,
  // would put the probes on wrong values.
  const int w = 33, h = 17;
  Heightfield hf(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) hf.at(x, y) = float(0.37 * x + 5.1 * y + 0.9 * std::sin(x * y));
  const double sx = 3.2, sy = 1.6, vs = 0.05;
  const auto place = pov::write_heightfield_png(hf, path("probe.png"), sx, sy, vs);
  std::string s = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#declare T = " +
                  pov::heightfield_sdl("probe.png", place, NAN);
  const int probes[][2] = {{0, 0}, {32, 0}, {0, 16}, {32, 16}, {7, 3}, {20, 11}, {31, 15}, {1, 14}};
  for (const auto& p : probes) {
    // World (x, y) of sample (col, row) is (col * dx, row * dy): POV <x, _, y>.
    // Edge samples are probed a hair inside: a ray exactly on the border of
    // the height_field's box may miss it. 1e-6 of the size moves the height
    // by < 1e-6 * 0.5 (the steepest slope here is ~0.5): far below a step.
    const double px = std::clamp(p[0] * sx / (w - 1), 1e-6 * sx, sx * (1 - 1e-6));
    const double pz = std::clamp(p[1] * sy / (h - 1), 1e-6 * sy, sy * (1 - 1e-6));
    s += "#declare N = <0, 0, 0>;\n#declare P = trace(T, " + pov::vec({px, 1000, pz}) +
         ", -y, N);\n#debug concat(\"FT_PROBE " + std::to_string(p[0]) + " " + std::to_string(p[1]) +
         " \", str(vlength(N), 0, 0), \" \", str(P.y, 0, 12), \"\\n\")\n";
  }
  s += "camera { location <1.6, 3, -2> look_at <1.6, 0, 0.8> }\nlight_source { <0, 10, -10> rgb 1 }\n"
       "object { T pigment { rgb 1 } }\n";
  io::write_file_atomically(path("probe.pov"), s);
  std::string messages;
  render(path("probe.pov"), 8, 6, 0, &messages);
  std::map<std::pair<int, int>, double> got;
  std::regex re("FT_PROBE (\\d+) (\\d+) (\\d) (-?[0-9.]+)");
  for (std::sregex_iterator it(messages.begin(), messages.end(), re), end; it != end; ++it) {
    ASSERT_EQ((*it)[3], "1") << "probe missed the terrain: " << (*it)[0];
    got[{std::stoi((*it)[1]), std::stoi((*it)[2])}] = std::stod((*it)[4]);
  }
  ASSERT_EQ(got.size(), std::size(probes)) << messages;
  // One 16-bit step of the height range is the precision the PNG keeps.
  const double step = (place.z_max - place.z_min) / 65535;
  for (const auto& p : probes) {
    const double want = hf.at(p[0], p[1]) * vs;
    const double g = got[{p[0], p[1]}];
    EXPECT_NEAR(g, want, step) << "sample col " << p[0] << " row " << p[1];
  }
}

TEST_F(PovTest, HighestPointLandsWhereTheCameraSays) {
  // A plain under a black sea with one steep cone standing out of it: the
  // tip is the topmost terrain point in its image column. Painted white
  // (emissive), the first white pixel from the top of that column must be
  // where Camera::project says.
  const int n = 65, cx = 44, cy = 19;
  Heightfield hf(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) hf.at(x, y) = float(std::max(0.0, 1 - std::hypot(x - cx, y - cy) / 8));
  pov::SceneParams p;
  p.terrain = &hf;
  p.world_size_x = p.world_size_y = 1;
  p.vertical_scale = 0.3;
  p.has_sea = true;
  p.sea_level = 0.01;
  p.camera.aspect = 160.0 / 120.0;
  p.camera.distance_scale = 2;  // the framing fits the cone tightly; leave room above it
  const auto sum = pov::write_scene(p, path("peak.pov"));
  io::write_file_atomically(path("peak_flat.pov"),
                        "#version 3.7;\n#declare FT_Sand_Tex = texture { pigment { rgb 1 } finish { emission 1 "
                        "diffuse 0 } }\n#declare FT_Grass_Tex = FT_Sand_Tex;\n#declare FT_Rock_Tex = "
                        "FT_Sand_Tex;\n#declare FT_Snow_Tex = FT_Sand_Tex;\n#declare FT_Sea_Tex = texture { pigment { rgb 0 } "
                        "finish { diffuse 0 } }\n#include \"peak.pov\"\n");
  const GrayImage img = render(path("peak_flat.pov"));
  double u, v;
  const Vec3 tip = pov::to_pov({cx / double(n - 1), cy / double(n - 1), 0.3});
  ASSERT_TRUE(sum.camera.project(tip, u, v));
  const int px = int(u * 160), py = int(v * 120);
  ASSERT_TRUE(px >= 0 && px < 160 && py >= 4 && py < 116) << "tip projects to " << px << ", " << py;
  // The cone (slope 67 degrees, steeper than the view) narrows to a point:
  // look in the tip's column and its neighbours for the first white pixel.
  int top = 120;
  for (int x = std::max(0, px - 1); x <= std::min(159, px + 1); ++x)
    for (int y = 0; y < top; ++y)
      if (luma(img, x, y) > 0.98) top = y;
  EXPECT_NEAR(top, py, 2) << "tip expected at row " << py << " of column " << px;
  EXPECT_LT(luma(img, px, std::max(0, py - 4)), 0.95) << "sky expected above the tip";
}

TEST_F(PovTest, ChunkedSweepRendersLikeOneSweep) {
  for (auto spline : {pov::SweepSpline::kLinear, pov::SweepSpline::kCubic}) {
    PolylineSet line = wiggle(301);
    for (size_t i = 0; i < line.radii.size(); ++i) line.radii[i] = 0.01 + 0.03 * double(i) / 300;  // taper
    std::string a, b;
    for (int64_t seg : {int64_t(24), int64_t(1) << 30}) {
      pov::SweepOptions o;
      o.spline = spline;
      o.segments_per_sweep = seg;
      const std::string s = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location <0.5, 1.2, "
                            "-0.2> look_at <0.5, 0, 0.1> angle 70 }\nlight_source { <-2, 5, -3> rgb 1 }\n"
                            "background { rgb 0.3 }\n" +
                            pov::sweeps_sdl(line, o, "pigment { rgb <1, 0.6, 0.2> }\n");
      const std::string f = path(std::string(seg == 24 ? "chunked" : "single") + ".pov");
      io::write_file_atomically(f, s);
      (seg == 24 ? a : b) = f;
    }
    const GrayImage ia = render(a), ib = render(b);
    // The tube covers a good part of the grey background...
    int drawn = 0, differ = 0;
    for (size_t i = 0; i < ia.pixels.size(); ++i) drawn += std::abs(int(ia.pixels[i]) - int(ia.pixels[0])) > 24;
    EXPECT_GT(drawn, int(ia.pixels.size() / 100)) << "spline " << int(spline);
    // ...and the same geometry gives the same picture: only pixels on the
    // silhouette may differ (root finding near grazing rays), < 2% of it.
    for (size_t i = 0; i < ia.pixels.size(); ++i) differ += std::abs(int(ia.pixels[i]) - int(ib.pixels[i])) > 24;
    EXPECT_LT(differ, drawn / 50 + 5) << "spline " << int(spline);
  }
}

TEST_F(PovTest, TerrainSceneWithCoastAndLightningRendersCleanly) {
  Heightfield hf(65, 65);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) hf.at(x, y) = float(1 - std::hypot(x - 32, y - 32) / 32 + 0.1 * std::sin(x * 0.7) * std::cos(y * 0.5));
  PolylineSet coast, bolt;
  for (int i = 0; i <= 128; ++i) {
    const double a = 2 * M_PI * i / 128;
    coast.add({0.5 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a), 0});
  }
  coast.end_line();
  for (int i = 0; i <= 64; ++i) bolt.add({0.6 + 0.03 * std::sin(i * 1.7), 0.4, 0.9 - 0.7 * i / 64.0}, 0.006 - 0.00005 * i);
  bolt.end_line();
  pov::SceneParams p;
  pov::set_scene_terrain(p, hf, 1, 0, 0.4);
  p.lines = {{&coast, pov::LineKind::kCoastline, 0}, {&bolt, pov::LineKind::kLightning, 0}};
  p.camera.aspect = 160.0 / 120.0;
  // A space and a quote in the names: the PNG's path is quoted and escaped.
  p.image_path = path("the \"island\" } sphere { 0, 1 }.png");
  pov::write_scene(p, path("scene with space.pov"));
  expect_not_blank(render(path("scene with space.pov"), 160, 120, 0.3), "terrain scene");
  EXPECT_TRUE(fs::exists(p.image_path));
}

TEST_F(PovTest, PolylineSceneRendersForEveryKind) {
  const PolylineSet line = wiggle(257);
  for (auto kind : {pov::LineKind::kGeneric, pov::LineKind::kLightning, pov::LineKind::kCoastline}) {
    const std::string f = path("line" + std::to_string(int(kind)) + ".pov");
    // Sized for the 160-pixel render: the automatic radius follows the picture.
    pov::write_polyline_scene(pov::SceneLines{&line, kind}, f, pov::polyline_camera(kind), 160);
    // The wiggle crosses ~85% of 160 pixels: a line >= 1 pixel wide and its
    // shadow stand out in >= 200 pixels (measured 1012, 5573 with the glow,
    // 1202); a blank picture has none.
    EXPECT_GE(standout_pixels(render(f)), 200) << "polyline scene of kind " << int(kind);
  }
}

TEST_F(PovTest, SceneToUnwritablePlaceFailsCleanlyWithNoPartialFile) {
  Heightfield hf(9, 9);
  for (size_t i = 0; i < hf.size(); ++i) hf.data()[i] = float(i % 7);
  pov::SceneParams p;
  p.terrain = &hf;
  // The folder does not exist: nothing at all may be written, PNG included.
  try {
    pov::write_scene(p, path("missing/scene.pov"));
    FAIL() << "expected FT_ERR_IO";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_IO);
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
  // /proc refuses new files even to root.
  EXPECT_THROW(pov::write_scene(p, "/proc/ft_scene.pov"), Error);
  // The scene's folder is fine but its PNG cannot be written: the scene must
  // not appear and no temporary file may stay behind.
  p.image_path = "/proc/ft_terrain.png";
  EXPECT_THROW(pov::write_scene(p, path("scene.pov")), Error);
  EXPECT_TRUE(fs::is_empty(dir_)) << "left a file in " << dir_;
}

TEST_F(PovTest, RenderCommandShowsPovrayErrorsAndWritesNothing) {
  io::write_file_atomically(path("bad.pov"), "#version 3.7;\nsphere { <0, 0, 0> 1 pigment { rgb 1 }\n");
  std::string out;
  const int rc = run_cli("render '" + path("bad.pov") + "' --width 32 --height 24 --out '" + path("bad.png") + "'", out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("Parse Error"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(path("bad.png")));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1) << "temporary file left";
}

TEST_F(PovTest, SceneCommandWritesAndRendersTerrainWithPolylines) {
  std::string out;
  ASSERT_EQ(run_cli("terrain --levels 6 --seed 5 --out '" + path("t.png") + "'", out), 0) << out;
  PolylineSet bolt = wiggle(129);
  std::ofstream(path("bolt.csv")) << "0.5,0.5,0.6\n0.52,0.5,0.4\n0.49,0.51,0.2\n0.5,0.5,0.05\n";
  ASSERT_EQ(run_cli("scene --terrain '" + path("t.png") + "' --sea-fraction 0.3 --polyline '" + path("bolt.csv") +
                        "' --kind lightning --pov '" + path("s.pov") + "' --render '" + path("s.png") +
                        "' --width 160 --height 120",
                    out),
            0)
      << out;
  expect_not_blank(io::read_png(path("s.png")), "fracterra scene --render");
}

// `fracterra planet --pov`: the isosurface over the equirectangular map and
// the exact cube-sphere as a mesh2 (--pov-geometry mesh2) are the same globe
// from the same camera. Inside the disc (luma above 0.15 in both: the
// background is 0.067) the two lumas correlate, r = 0.974. This test found
// that FT_Planet read its height map as sRGB (heights sunk as h^2.2): 0.926
// then; pov_globe_mesh without its x -> -x (a mirrored globe) gave 0.58, the
// isosurface mirrored left-right 0.34, seen from 90 degrees further east
// 0.14. Deterministic renders; 0.95 keeps all four out. Both render with no
// warning. ~4 s.
TEST_F(PovTest, PlanetMesh2AndIsosurfaceRenderTheSameGlobe) {
  std::string out;
  const std::string planet = "planet --octaves 7 --seed 7 --sea-fraction 0.6 --exaggeration 30 ";
  ASSERT_EQ(run_cli(planet + "--size 512x256 --pov '" + path("iso.pov") + "'", out), 0) << out;
  ASSERT_EQ(run_cli(planet + "--pov-geometry mesh2 --level 6 --pov '" + path("mesh.pov") + "'", out), 0) << out;
  const std::string scene = [&] {
    std::ifstream f(path("mesh.pov"));
    return std::string(std::istreambuf_iterator<char>(f), {});
  }();
  EXPECT_NE(scene.find("FT_Planet_Mesh(FT_Planet_Mesh2"), std::string::npos);
  EXPECT_NE(scene.find("FT_Planet_Sea("), std::string::npos);
  EXPECT_TRUE(fs::exists(path("mesh_mesh.inc")));
  EXPECT_FALSE(fs::exists(path("mesh_height.png")));
  const GrayImage iso = render(path("iso.pov"), 96, 96), mesh = render(path("mesh.pov"), 96, 96);
  expect_not_blank(iso, "the isosurface planet");
  expect_not_blank(mesh, "the mesh2 planet");
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  int n = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      const double a = luma(iso, x, y), b = luma(mesh, x, y);
      if (a < 0.15 || b < 0.15) continue;  // the background, or the limb of one only
      sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b, ++n;
    }
  ASSERT_GT(n, 96 * 96 / 3) << "the globe fills about half the picture";
  const double cov = sab / n - sa / n * sb / n;
  const double r = cov / std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
  std::printf("mesh2 against isosurface: r = %.3f over %d pixels\n", r, n);
  EXPECT_GT(r, 0.95) << "the mesh2 and the isosurface show different globes";
  // Bad input: a clear message, no scene.
  out.clear();
  EXPECT_NE(run_cli(planet + "--pov-geometry mesh2 --level 13 --pov '" + path("bad.pov") + "'", out), 0);
  EXPECT_NE(out.find("level"), std::string::npos) << out;
  out.clear();
  EXPECT_NE(run_cli(planet + "--pov-geometry mesh2 --out '" + path("m.ply") + "' --pov '" + path("bad.pov") + "'",
                    out), 0);
  EXPECT_NE(out.find("--pov-geometry mesh2"), std::string::npos) << out;
  out.clear();
  EXPECT_NE(run_cli(planet + "--pov-geometry sphere --pov '" + path("bad.pov") + "'", out), 0);
  EXPECT_NE(out.find("pov-geometry"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(path("bad.pov")));
}

// `fracterra polyline ... --pov` (asked for, and missing before): a framed
// sphere_sweep scene of the line that the real POV-Ray renders.
TEST_F(PovTest, PolylineCommandWritesAFramedSceneThatRenders) {
  std::string out;
  ASSERT_EQ(run_cli("polyline --method fpl --depth 10 --seed 3 --out '" + path("l.csv") + "' --pov '" +
                        path("l.pov") + "' --render '" + path("l.png") + "' --width 160 --height 120",
                    out),
            0)
      << out;
  const std::string sdl = io::read_file(path("l.pov"));
  EXPECT_NE(sdl.find("sphere_sweep { linear_spline"), std::string::npos);
  EXPECT_NE(sdl.find("camera {"), std::string::npos);
  EXPECT_NE(sdl.find("the file's radii as taper"), std::string::npos);
  EXPECT_GE(standout_pixels(io::read_png(path("l.png"))), 200) << "fracterra polyline --pov --render";
  // Branching lines are drawn as lightning unless --kind says otherwise.
  ASSERT_EQ(run_cli("polyline --method fpl3d --depth 7 --branch-prob 0.05 --pov '" + path("b.pov") + "'", out), 0)
      << out;
  EXPECT_NE(io::read_file(path("b.pov")).find(": lightning,"), std::string::npos);
  ASSERT_EQ(run_cli("polyline --method fpl --depth 7 --kind coastline --pov '" + path("c.pov") + "'", out), 0) << out;
  EXPECT_NE(io::read_file(path("c.pov")).find(": coastline,"), std::string::npos);
  EXPECT_EQ(run_cli("polyline --method fpl --depth 4 --render '" + path("x.png") + "'", out), 1);
  EXPECT_NE(out.find("--render needs --pov"), std::string::npos) << out;
}

// `scene --radius` overrides the radii stored in a polyline file (before, it
// applied only to vertices without one), `--radius-scale` multiplies, and
// `--radius-from-file` keeps the stored ones as world units.
TEST_F(PovTest, SceneRadiusOptionsOverrideScaleOrKeepTheFileRadii) {
  std::ofstream(path("l.csv")) << "0,0,0,0.01\n1,0.3,0,0.01\n1.5,0.1,0,0.01\n";
  auto radius_comment = [&](const std::string& flags) {
    std::string out;
    EXPECT_EQ(run_cli("scene --polyline '" + path("l.csv") + "' " + flags + " --pov '" + path("s.pov") + "'", out), 0)
        << out;
    const std::string sdl = io::read_file(path("s.pov"));
    const size_t at = sdl.find(" vertices, radius ");
    return at == std::string::npos ? -1.0 : std::stod(sdl.substr(at + 18));
  };
  const double automatic = radius_comment("");
  EXPECT_GT(automatic, 0);
  EXPECT_LT(automatic, 0.01);  // sized from the picture, not the file's 0.01
  EXPECT_DOUBLE_EQ(radius_comment("--radius 0.002"), 0.002);
  EXPECT_DOUBLE_EQ(radius_comment("--radius 0.002 --radius-scale 3"), 0.006);
  EXPECT_NE(io::read_file(path("s.pov")).find(", 0.006\n"), std::string::npos);
  radius_comment("--radius-from-file");
  EXPECT_NE(io::read_file(path("s.pov")).find(", 0.01\n"), std::string::npos);  // the stored radius
  EXPECT_GE(standout_pixels(render(path("s.pov"))), 200) << "scene with the file's radii";
}

TEST_F(PovTest, MacrosFailWithClearErrorsOnBadInput) {
  // FT_FPL bounds its recursion depth (POV-Ray nests ~98 macro calls).
  io::write_file_atomically(path("deep.pov"), "#version 3.7;\n#include \"ft_fpl.inc\"\n#declare P = FT_FPL(<0,0,0>, "
                                          "<1,0,0>, y, 0.1, false, 0, 120, seed(1));\n");
  try {
    render(path("deep.pov"), 8, 6);
    FAIL() << "expected povray to stop";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("FT_FPL: Depth must be"), std::string::npos) << e.what();
  }
}


// fracterra scene --tiles: 4 x 4 height_fields edge to edge. trace() probes a
// hair (1e-6 of a sample) either side of every seam, at sample nodes and
// between them: every probe hits (no crack lets a ray through) and the two
// sides give the same height (no step) to 1e-3 of a 16-bit step plus what
// the slope adds over 2e-6 of a sample (together well under one 16-bit
// step, so tiles scaled apart by a single step would fail). The render is
// not blank.
TEST_F(PovTest, TiledSceneHasNoCracksAlongTheSeams) {
  std::string out;
  ASSERT_EQ(run_cli("tiles --levels 8 --hurst 0.6 --seed 9 --tile 64 --quiet --out '" + path("set") + "'", out), 0)
      << out;
  ASSERT_EQ(run_cli("scene --tiles '" + path("set") + "' --pov '" + path("tiled.pov") + "'", out), 0) << out;
  const std::string scene = io::read_file(path("tiled.pov"));
  size_t fields = 0;
  for (size_t at = scene.find("png \""); at != std::string::npos; at = scene.find("png \"", at + 1)) ++fields;
  EXPECT_EQ(fields, 16u);
  // World size 10 over 256 cells: seams at x (z in POV) = 64 k s, s = 10 / 256.
  const double s = 10.0 / 256, eps = 1e-6 * s;
  std::string probe = "#version 3.7;\n#include \"tiled.pov\"\n#declare Misses = 0;\n#declare Worst = 0;\n#declare Hits = 0;\n"
                      "#macro Probe(X, Z, DX, DZ)\n"
                      "  #local N1 = <0, 0, 0>; #local N2 = <0, 0, 0>;\n"
                      "  #local P1 = trace(FT_Terrain_Object, <X - DX, 1000, Z - DZ>, -y, N1);\n"
                      "  #local P2 = trace(FT_Terrain_Object, <X + DX, 1000, Z + DZ>, -y, N2);\n"
                      "  #if (vlength(N1) = 0 | vlength(N2) = 0) #declare Misses = Misses + 1;\n"
                      "  #else #declare Hits = Hits + 2; #declare Worst = max(Worst, abs(P1.y - P2.y)); #end\n"
                      "#end\n";
  for (int k = 1; k <= 3; ++k)
    for (int t = 1; t < 512; ++t) {  // along the seam, every half sample (nodes and cell middles)
      const double along = t * 0.5 * s, at = 64 * k * s;
      probe += "Probe(" + pov::number(at) + ", " + pov::number(along) + ", " + pov::number(eps) + ", 0)\n";
      probe += "Probe(" + pov::number(along) + ", " + pov::number(at) + ", 0, " + pov::number(eps) + ")\n";
    }
  probe += "#debug concat(\"FT_SEAMS \", str(Hits, 0, 0), \" \", str(Misses, 0, 0), \" \", str(Worst, 0, 12), \"\\n\")\n";
  io::write_file_atomically(path("probe.pov"), probe);
  std::string messages;
  const GrayImage img = render(path("probe.pov"), 160, 120, 0, &messages);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(messages, m, std::regex("FT_SEAMS (\\d+) (\\d+) ([0-9.]+)"))) << messages;
  EXPECT_EQ(std::stoi(m[1]), 2 * 2 * 3 * 511);
  EXPECT_EQ(std::stoi(m[2]), 0) << "rays passed through a seam";
  const nlohmann::json manifest = nlohmann::json::parse(io::read_file(path("set/manifest.json")));
  const double range = manifest["height_range"]["max"].get<double>() - manifest["height_range"]["min"].get<double>();
  // The steepest slope of this terrain is below 40 height units per unit of x.
  EXPECT_LE(std::stod(m[3]), 1e-3 * range / 65535 + 40 * 2 * eps);
  EXPECT_LT(1e-3 * range / 65535 + 40 * 2 * eps, range / 65535);
  expect_not_blank(img, "tiled scene");
}

}  // namespace
}  // namespace ft

namespace ft {
namespace {

// `fracterra scene --rivers`: the rivers and lakes of an eroded terrain show
// (the picture changes where they are) and POV-Ray parses them cleanly.
TEST_F(PovTest, SceneWithRiversAndLakesShowsThem) {
  std::string out;
  ASSERT_EQ(run_cli("terrain --method fbm --size 129 --seed 4 --erode valleys --out '" + path("t.png") + "'", out),
            0)
      << out;
  ASSERT_EQ(run_cli("rivers --in '" + path("t.png") + "' --min-area 0.05 --min-lake-area 0.001 --out '" +
                        path("r.json") + "'",
                    out),
            0)
      << out;
  GrayImage img[2];
  for (int k = 0; k < 2; ++k) {
    const std::string rivers = k ? " --rivers '" + path("r.json") + "'" : "";
    ASSERT_EQ(run_cli("scene --terrain '" + path("t.png") + "'" + rivers + " --camera-elevation-deg 60 --pov '" +
                          path("s" + std::to_string(k) + ".pov") + "'",
                      out),
              0)
        << out;
    img[k] = render(path("s" + std::to_string(k) + ".pov"));
  }
  int64_t changed = 0;
  for (size_t i = 0; i < img[0].pixels.size(); ++i)
    changed += std::fabs(double(img[0].pixels[i]) - img[1].pixels[i]) > 0.05 * (img[0].bit_depth == 16 ? 65535 : 255);
  EXPECT_GT(changed, 100) << "the rivers do not show";
  std::ifstream scene(path("s1.pov"));
  const std::string text((std::istreambuf_iterator<char>(scene)), std::istreambuf_iterator<char>());
  const size_t rivers = text.find("// rivers:");
  ASSERT_NE(rivers, std::string::npos);
  EXPECT_EQ(text.find("mesh2 {", rivers), text.find('\n', rivers) + 1) << "the rivers are not one ribbon mesh";
  EXPECT_NE(text.find("FT_Water_Tex"), std::string::npos);
}

// povray_macros/ft_water.inc on its own: FT_River and FT_Lake in a user's scene.
TEST_F(PovTest, WaterMacrosRenderARiverAndALake) {
  std::ofstream(path("w.pov")) << R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "ft_water.inc"
camera { location <0.5, 2, -0.3> look_at <0.5, 0, 0.5> }
light_source { <2, 5, -3> color rgb 1 }
plane { y, 0 pigment { rgb <0.95, 0.9, 0.8> } }
#declare P = array[4] { <0.1, 0.05, 0.1>, <0.3, 0.04, 0.4>, <0.5, 0.03, 0.5>, <0.9, 0.02, 0.9> };
#declare R = array[4] { 0.04, 0.06, 0.08, 0.1 };
FT_River(P, R)
#declare L = array[5] { <0.5, 0.05>, <0.95, 0.05>, <0.95, 0.45>, <0.5, 0.45>, <0.5, 0.05> };
FT_Lake(L, 0.01, 0.005)
)";
  expect_not_blank(render(path("w.pov")), "ft_water.inc");
}

// FT_River's ribbon lies in its bed on a steep stretch too: a river falling
// at 45 degrees, radius 0.1, probed from straight above its centreline with
// trace(). Its surface there stands FT_River_Flat r / cos(45) = 0.042 over
// the centreline (the ellipse square to the flow; 8 sides: its top vertex
// is exact, so 0.0425 holds it with rounding); the old vertically squashed
// sweep stood r sqrt(0.09 + 1) = 0.104 over it. A level stretch: 0.03.
TEST_F(PovTest, WaterMacroRiverLiesInItsBedOnASteepSlope) {
  std::ofstream(path("steep.pov")) << R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "ft_water.inc"
#declare P = array[4] { <0, 2, 0>, <1, 1, 0>, <2, 0, 0>, <3, 0, 0> };
#declare R = array[4] { 0.1, 0.1, 0.1, 0.1 };
#declare River = object { FT_River(P, R) }
#macro Over(X, Centre, Most)
  #local N = <0, 0, 0>;
  #local Hit = trace(River, <X, 10, 0>, -y, N);
  #if (vlength(N) = 0) #error concat("nothing under x = ", str(X, 0, 3), "
") #end
  #local Rise = Hit.y - Centre;
  #debug concat("river surface over its centreline at x = ", str(X, 0, 3), ": ", str(Rise, 0, 4), "
")
  #if (Rise > Most | Rise < 0.9 * Most) #error concat("the ribbon stands ", str(Rise, 0, 4), " over its centreline
") #end
#end
Over(0.5, 1.5, 0.0425)
Over(2.5, 0, 0.0301)
camera { location <1.5, 3, -3> look_at <1.5, 0.5, 0> }
light_source { <2, 5, -3> color rgb 1 }
object { River }
)";
  expect_not_blank(render(path("steep.pov")), "FT_River on a slope");
}

}  // namespace
}  // namespace ft

namespace ft {
namespace {

// Another program's lights in their physical units (Blender's Cycles: W, or
// W/m^2 for a sun) light a grey Lambertian plane, seen from straight above, to
// albedo x E / pi, with E the irradiance the formulas of docs/povray.md give;
// the render is read back through sRGB. Tolerance: 1.5% (an 8-bit sRGB step at
// these levels is 0.4-0.8%, and the patch read is 1/10 of the frame across,
// whose off-axis cosines lower a point light's mean by at most 0.5%).
class PovLightsTest : public PovTest {
 protected:
  static constexpr double kAlbedo = 0.18;
  static constexpr double kPi = 3.14159265358979323846;
  // Linear value of the frame's central 10% square.
  double centre(const pov::SceneLight& light, double h_extent = 4) {
    Mesh plane;
    plane.positions = {-50, -50, 0, 50, -50, 0, 50, 50, 0, -50, 50, 0};
    plane.face_sizes = {4};
    plane.face_indices = {0, 1, 2, 3};
    pov::SceneParams p;
    pov::SceneMaterial grey;
    grey.color = {kAlbedo, kAlbedo, kAlbedo};
    grey.roughness = 1, grey.specular = 0;
    p.meshes.push_back({&plane, grey, false});
    p.scene_light = true;
    p.lights = {light};
    p.camera_given = true;
    p.camera_pose = {{0, 0, 10}, {0, 0, -10}, {h_extent, 0, 0}, {0, h_extent, 0}};
    pov::write_scene(p, path("lit.pov"));
    const io::ChannelImage img = io::read_png_channels(render_rgb(path("lit.pov"), 40, 40));
    double sum = 0;
    int n = 0;
    for (int y = 18; y < 22; ++y)
      for (int x = 18; x < 22; ++x, ++n) {
        const double v = img.samples[(size_t(y) * img.width + x) * img.channels] / double((1 << img.bit_depth) - 1);
        sum += v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
      }
    return sum / n;
  }
  std::string render_rgb(const std::string& scene, int w, int h) {
    pov::RenderOptions o;
    o.width = w, o.height = h, o.antialias = 0;
    const std::string out = path("lit.png");
    const pov::RenderResult r = pov::render_scene(scene, out, o);
    EXPECT_EQ(r.warnings, 0) << r.messages;
    return out;
  }
};

TEST_F(PovLightsTest, SunOfStrengthSLightsToAlbedoTimesSOverPi) {
  pov::SceneLight sun;
  sun.kind = pov::LightKind::kSun, sun.power = 3, sun.direction = {0, 0, -1};
  EXPECT_NEAR(centre(sun), kAlbedo * 3 / kPi, 0.015 * kAlbedo * 3 / kPi);
}

TEST_F(PovLightsTest, PointLightOfPowerPFollowsTheInverseSquareLaw) {
  for (double h : {2.0, 5.0}) {
    pov::SceneLight point;
    point.kind = pov::LightKind::kPoint, point.power = 300, point.location = {0, 0, h};
    const double want = kAlbedo * 300 / (4 * kPi * h * h) / kPi;
    EXPECT_NEAR(centre(point, 0.2 * h), want, 0.015 * want) << "height " << h;
  }
}

TEST_F(PovLightsTest, SpotLightIsThePointLightInItsConeAndDarkOutside) {
  pov::SceneLight spot;
  spot.kind = pov::LightKind::kSpot, spot.power = 1000, spot.location = {0, 0, 4}, spot.direction = {0, 0, -1};
  spot.spot_size_deg = 40, spot.spot_blend = 0.2;
  const double want = kAlbedo * 1000 / (4 * kPi * 16) / kPi;
  EXPECT_NEAR(centre(spot, 0.8), want, 0.015 * want);
  spot.direction = {1, 0, -0.3};  // the cone turned away from the patch
  EXPECT_LT(centre(spot, 0.8), 0.002);
}

TEST_F(PovLightsTest, AreaLightOfFluxPIsALambertianEmitter) {
  pov::SceneLight area;
  area.kind = pov::LightKind::kArea, area.power = 400, area.location = {0, 0, 4}, area.direction = {0, 0, -1};
  area.area_u = {0.2, 0, 0}, area.area_v = {0, 0.2, 0};
  const double want = kAlbedo * 400 / (kPi * 16) / kPi;  // intensity P / pi on the axis
  EXPECT_NEAR(centre(area, 0.8), want, 0.015 * want);
  area.direction = {0, 0, 1};  // facing away: one-sided
  EXPECT_LT(centre(area, 0.8), 0.002);
}

}  // namespace
}  // namespace ft
