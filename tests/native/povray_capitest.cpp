// SPDX-License-Identifier: GPL-3.0-or-later
// The POV-Ray exporter through the C ABI, as ctypes and the Blender
// exporter call it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path dir = fs::temp_directory_path() / ("ft_pov_capi_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(dir); }
  ~TempDir() { fs::remove_all(dir); }
  std::string operator/(const std::string& n) const { return (dir / n).string(); }
};

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(PovCapi, WritesASceneWithTerrainAndLines) {
  TempDir t;
  std::vector<float> z(17 * 9);
  for (size_t i = 0; i < z.size(); ++i) z[i] = float(std::sin(i * 0.37));
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_heightfield_create(17, 9, z.data(), &hf), FT_OK);
  const double xyz[] = {0.1, 0.1, 0.5, 0.2, 0.3, 0.4, 0.3, 0.2, 0.1};
  ft_polylines* pl = nullptr;
  ASSERT_EQ(ft_polylines_create(xyz, nullptr, 3, nullptr, 1, &pl), FT_OK);
  ft_pov_scene_params p;
  ASSERT_EQ(ft_pov_scene_params_init(&p), FT_OK);
  p.terrain = hf;
  p.vertical_scale = 0.1;
  p.has_sea = 1;
  ft_pov_scene_lines lines = {pl, FT_POV_LIGHTNING, 0};
  p.lines = &lines;
  p.line_set_count = 1;
  ASSERT_EQ(ft_pov_write_scene(&p, (t / "s.pov").c_str()), FT_OK) << ft_last_error();
  const std::string sdl = slurp(t / "s.pov");
  EXPECT_NE(sdl.find("png \"s.terrain.png\""), std::string::npos);
  EXPECT_NE(sdl.find("FT_Lightning_Tex"), std::string::npos);
  EXPECT_TRUE(fs::exists(t / "s.terrain.png"));
  ft_polylines_free(pl);
  ft_heightfield_free(hf);
}

TEST(PovCapi, TheDefaultCameraElevationIsAutoByWhatTheSceneHolds) {
  // camera_elevation_deg 0 (the default) frames a terrain from 22 degrees,
  // polylines alone from 70 and lightning alone from 12: each auto scene is
  // the one written with that elevation given, byte for byte. Before auto,
  // the C ABI framed polylines alone from 22, unlike the CLI.
  TempDir t;
  std::vector<float> z(17 * 17);
  for (size_t i = 0; i < z.size(); ++i) z[i] = float(std::sin(i * 0.37));
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_heightfield_create(17, 17, z.data(), &hf), FT_OK);
  const double xyz[] = {0.1, 0.1, 0.5, 0.2, 0.3, 0.4, 0.3, 0.2, 0.1, 0.6, 0.1, 0.2};
  ft_polylines* pl = nullptr;
  ASSERT_EQ(ft_polylines_create(xyz, nullptr, 4, nullptr, 1, &pl), FT_OK);
  auto scene = [&](const ft_heightfield* terrain, int32_t kind, double elevation, const char* dir) {
    fs::create_directories(t / dir);
    ft_pov_scene_params p;
    EXPECT_EQ(ft_pov_scene_params_init(&p), FT_OK);
    p.terrain = terrain;
    ft_pov_scene_lines lines = {pl, kind, 0.01};
    p.lines = &lines;
    p.line_set_count = 1;
    p.camera_elevation_deg = elevation;
    EXPECT_EQ(ft_pov_write_scene(&p, (t / (std::string(dir) + "/s.pov")).c_str()), FT_OK) << ft_last_error();
    return slurp(t / (std::string(dir) + "/s.pov"));
  };
  ft_pov_scene_params d;
  ft_pov_scene_params_init(&d);
  EXPECT_EQ(d.camera_elevation_deg, 0.0) << "auto is the default";
  EXPECT_EQ(scene(nullptr, FT_POV_LINE, 0, "a"), scene(nullptr, FT_POV_LINE, 70, "b"));
  EXPECT_NE(scene(nullptr, FT_POV_LINE, 0, "a"), scene(nullptr, FT_POV_LINE, 22, "b")) << "control";
  EXPECT_EQ(scene(nullptr, FT_POV_LIGHTNING, 0, "a"), scene(nullptr, FT_POV_LIGHTNING, 12, "b"));
  EXPECT_EQ(scene(hf, FT_POV_LIGHTNING, 0, "a"), scene(hf, FT_POV_LIGHTNING, 22, "b"));
  ft_polylines_free(pl);
  ft_heightfield_free(hf);
}

TEST(PovCapi, CameraMarginAndCentreAreSettingsOfTheTable) {
  // margin and center_v are rows of ft_pov_scene_params (ABI 2.11): their
  // defaults are CameraOptions', the table checks their ranges in its words,
  // they reach the framing, and a 2.10 caller's smaller struct gets the defaults.
  TempDir t;
  std::vector<float> z(17 * 17);
  for (size_t i = 0; i < z.size(); ++i) z[i] = float(std::cos(i * 0.21));
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_heightfield_create(17, 17, z.data(), &hf), FT_OK);
  ft_pov_scene_params p;
  ASSERT_EQ(ft_pov_scene_params_init(&p), FT_OK);
  EXPECT_EQ(p.camera_margin, 0.04);
  EXPECT_EQ(p.camera_center_v, 0.55);
  p.terrain = hf;
  ASSERT_EQ(ft_pov_write_scene(&p, (t / "default.pov").c_str()), FT_OK) << ft_last_error();
  const std::string by_default = slurp(t / "default.pov");
  p.camera_center_v = 0.9;
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "x.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("camera_center_v must be in [0.2, 0.8], got 0.9"), std::string::npos)
      << ft_last_error();
  p.camera_center_v = 0.55;
  p.camera_margin = 0.6;
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "x.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("camera_margin must be in [0, 0.5], got 0.6"), std::string::npos)
      << ft_last_error();
  p.camera_margin = 0.04;
  p.camera_elevation_deg = 0.5;  // 0 is auto; between 0 and 1 is neither
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "x.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("camera_elevation_deg must be 0 (auto) or in [1, 90], got 0.5"),
            std::string::npos)
      << ft_last_error();
  EXPECT_FALSE(fs::exists(t / "x.pov"));
  p.camera_elevation_deg = 0;
  p.camera_center_v = 0.7;
  p.camera_margin = 0.2;
  ASSERT_EQ(ft_pov_write_scene(&p, (t / "moved.pov").c_str()), FT_OK) << ft_last_error();
  EXPECT_NE(slurp(t / "moved.pov"), by_default) << "margin and center_v reach the camera";
  // A caller of ABI 2.10 knows neither field: its struct ends before them.
  ft_pov_scene_params old;
  ft_pov_scene_params_init(&old);
  old.terrain = hf;
  old.struct_size = offsetof(ft_pov_scene_params, camera_margin);
  old.camera_margin = old.camera_center_v = -1;  // beyond its size: never read
  ASSERT_EQ(ft_pov_write_scene(&old, (t / "default.pov").c_str()), FT_OK) << ft_last_error();
  EXPECT_EQ(slurp(t / "default.pov"), by_default);
  ft_heightfield_free(hf);
}

TEST(PovCapi, AGivenCameraColoursAndLightAreWrittenAsGiven) {
  // ABI 2.17: another program's camera, terrain colours and light. The camera
  // statement holds the vectors in POV axes (world y and z swapped), the
  // colours become an sRGB PNG beside the scene, the light the background
  // and ambient; a flat camera, bad colours and a too bright sky are refused.
  TempDir t;
  std::vector<float> z(9 * 5, 0.25f);
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_heightfield_create(9, 5, z.data(), &hf), FT_OK);
  std::vector<float> rgb(9 * 5 * 3, 0.5f);
  ft_pov_scene_params p;
  ASSERT_EQ(ft_pov_scene_params_init(&p), FT_OK);
  EXPECT_EQ(p.camera_given, 0);
  EXPECT_EQ(p.terrain_colors, nullptr);
  EXPECT_EQ(p.has_scene_light, 0);
  EXPECT_EQ(p.sun_color[2], 1.0);
  p.terrain = hf;
  p.camera_given = 1;
  const double location[] = {0.5, -2, 1}, direction[] = {0, 1.5, -0.5}, right[] = {1.2, 0, 0}, up[] = {0, 0.2, 0.6};
  for (int k = 0; k < 3; ++k)
    p.camera_location[k] = location[k], p.camera_direction[k] = direction[k], p.camera_right[k] = right[k],
    p.camera_up[k] = up[k];
  p.terrain_colors = rgb.data();
  p.has_scene_light = 1;
  p.sky_color[0] = p.sky_color[1] = p.sky_color[2] = 0.25;
  ASSERT_EQ(ft_pov_write_scene(&p, (t / "s.pov").c_str()), FT_OK) << ft_last_error();
  const std::string sdl = slurp(t / "s.pov");
  EXPECT_NE(sdl.find("location <0.5, 1, -2>\n  right <1.2, 0, 0>\n  up <0, 0.6, 0.2>\n  direction <0, -0.5, 1.5>"),
            std::string::npos)
      << sdl;
  EXPECT_NE(sdl.find("image_map { png \"s.colors.png\" gamma srgb interpolate 2 }"), std::string::npos);
  EXPECT_NE(sdl.find("ambient_light rgb <0.25, 0.25, 0.25>"), std::string::npos);
  EXPECT_NE(sdl.find("background { rgb <0.25, 0.25, 0.25> }"), std::string::npos);
  EXPECT_EQ(sdl.find("sky_sphere"), std::string::npos);
  EXPECT_TRUE(fs::exists(t / "s.colors.png"));

  p.camera_up[0] = 0.6, p.camera_up[1] = p.camera_up[2] = 0;  // parallel to right
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "x.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("must span space"), std::string::npos) << ft_last_error();
  p.camera_up[0] = 0, p.camera_up[2] = 0.6;
  rgb[7] = NAN;
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "x.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("terrain colours must be finite and >= 0"), std::string::npos)
      << ft_last_error();
  rgb[7] = 0.5f;
  p.sky_color[1] = 2000;
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "x.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("sky_color"), std::string::npos) << ft_last_error();
  EXPECT_FALSE(fs::exists(t / "x.pov"));
  ft_heightfield_free(hf);
}

TEST(PovCapi, RejectsBadArgumentsWithMessages) {
  TempDir t;
  ft_pov_scene_params p;
  ASSERT_EQ(ft_pov_scene_params_init(&p), FT_OK);
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "s.pov").c_str()), FT_ERR_INVALID_ARGUMENT);  // nothing to show
  EXPECT_NE(std::string(ft_last_error()).find("a terrain, a polyline set or a mesh"), std::string::npos);
  EXPECT_EQ(ft_pov_write_scene(nullptr, "x.pov"), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_pov_write_scene(&p, nullptr), FT_ERR_INVALID_ARGUMENT);
  p.struct_size = 8;
  EXPECT_EQ(ft_pov_write_scene(&p, (t / "s.pov").c_str()), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("struct_size"), std::string::npos);
  EXPECT_EQ(ft_pov_scene_params_init(nullptr), FT_ERR_INVALID_ARGUMENT);

  const double xyz[] = {0, 0, 0, 1, 0, 0};
  ft_polylines* pl = nullptr;
  ASSERT_EQ(ft_polylines_create(xyz, nullptr, 2, nullptr, 1, &pl), FT_OK);
  ft_pov_sweep_params sp;
  ASSERT_EQ(ft_pov_sweep_params_init(&sp), FT_OK);
  EXPECT_EQ(ft_pov_write_sweeps(pl, &sp, (t / "a.inc").c_str(), "bolt } sphere {"), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("identifier"), std::string::npos);
  sp.segments_per_sweep = 0;
  EXPECT_EQ(ft_pov_write_sweeps(pl, &sp, (t / "a.inc").c_str(), "Bolt"), FT_ERR_INVALID_ARGUMENT);
  EXPECT_FALSE(fs::exists(t / "a.inc"));
  ft_polylines_free(pl);
}

TEST(PovCapi, LowerLevelWritersForOtherExporters) {
  TempDir t;
  std::vector<float> z = {0, 1, 2, 3};
  ft_heightfield* hf = nullptr;
  ASSERT_EQ(ft_heightfield_create(2, 2, z.data(), &hf), FT_OK);
  double lo = 0, hi = 0;
  ASSERT_EQ(ft_pov_write_heightfield(hf, (t / "h.png").c_str(), (t / "h.inc").c_str(), "Terrain", 10, 10, 2,
                                     &lo, &hi),
            FT_OK)
      << ft_last_error();
  EXPECT_EQ(lo, 0);
  EXPECT_EQ(hi, 6);
  EXPECT_NE(slurp(t / "h.inc").find("#declare Terrain = height_field {\n  png \"h.png\""), std::string::npos);
  const double xyz[] = {0, 0, 0, 1, 0, 0, 2, 1, 0};
  const double radii[] = {0.3, 0.2, 0.1};
  ft_polylines* pl = nullptr;
  ASSERT_EQ(ft_polylines_create(xyz, radii, 3, nullptr, 1, &pl), FT_OK);
  ft_pov_sweep_params sp;
  ft_pov_sweep_params_init(&sp);
  ASSERT_EQ(ft_pov_write_sweeps(pl, &sp, (t / "b.inc").c_str(), "Bolt"), FT_OK) << ft_last_error();
  EXPECT_NE(slurp(t / "b.inc").find("#declare Bolt = object {\nsphere_sweep { linear_spline 3,"), std::string::npos);
  ft_polylines_free(pl);
  ft_heightfield_free(hf);
}

}  // namespace

namespace {

// Another program's scene through the ABI (2.26): a mesh in a material under a
// point light writes the converted light and a mesh2; bad lights, materials
// and meshes are refused naming what is wrong, and nothing is written.
struct BlenderScene {
  TempDir t;
  ft_mesh* mesh = nullptr;
  ft_pov_light light{};
  ft_pov_scene_mesh entry{};
  ft_pov_scene_params p{};
  BlenderScene() {
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const int32_t sizes[] = {4}, indices[] = {0, 1, 2, 3};
    EXPECT_EQ(ft_mesh_create(positions, 4, sizes, 1, indices, nullptr, nullptr, 0, &mesh), FT_OK) << ft_last_error();
    light.kind = FT_POV_LIGHT_POINT;
    light.color[0] = light.color[1] = light.color[2] = 1;
    light.power = 1000;
    light.location[2] = 3;
    light.direction[2] = -1;
    light.shadows = 1;
    entry.mesh = mesh;
    entry.material = {{0.5, 0.4, 0.3}, {0, 0, 0}, 0.5, 0.5, 0};
    ft_pov_scene_params_init(&p);
    p.has_scene_light = 1;
    p.lights = &light;
    p.light_count = 1;
    p.meshes = &entry;
    p.mesh_count = 1;
  }
  ~BlenderScene() { ft_mesh_free(mesh); }
  ft_status write() { return ft_pov_write_scene(&p, (t / "b.pov").c_str()); }
};

TEST(PovCapi, AnotherProgramsLightsAndMeshesAreWrittenConverted) {
  BlenderScene s;
  ASSERT_EQ(s.write(), FT_OK) << ft_last_error();
  const std::string sdl = slurp(s.t / "b.pov");
  EXPECT_NE(sdl.find("fade_power 2"), std::string::npos);
  EXPECT_NE(sdl.find("mesh2 {"), std::string::npos);
  EXPECT_EQ(sdl.find("plane { y"), std::string::npos) << "another program's scene gets no ground of fracterra's";
}

TEST(PovCapi, BadLightsMaterialsAndMeshesAreRefusedNamingTheField) {
  const struct {
    const char* what;
    void (*spoil)(BlenderScene&);
  } cases[] = {
      {"light kind", [](BlenderScene& s) { s.light.kind = 7; }},
      {"light power", [](BlenderScene& s) { s.light.power = NAN; }},
      {"light color", [](BlenderScene& s) { s.light.color[1] = -1; }},
      {"direction", [](BlenderScene& s) { s.light.kind = FT_POV_LIGHT_SPOT, s.light.direction[2] = 0; }},
      {"spot_size_deg", [](BlenderScene& s) { s.light.kind = FT_POV_LIGHT_SPOT, s.light.spot_size_deg = 200; }},
      {"area_u", [](BlenderScene& s) { s.light.kind = FT_POV_LIGHT_AREA; }},
      {"lights", [](BlenderScene& s) { s.p.lights = nullptr; }},
      {"light_count", [](BlenderScene& s) { s.p.light_count = -1; }},
      {"mesh material color", [](BlenderScene& s) { s.entry.material.color[0] = 2; }},
      {"mesh material roughness", [](BlenderScene& s) { s.entry.material.roughness = NAN; }},
      {"meshes[i].mesh", [](BlenderScene& s) { s.entry.mesh = nullptr; }},
      {"mesh_count", [](BlenderScene& s) { s.p.mesh_count = 70000; }},
  };
  for (const auto& c : cases) {
    BlenderScene s;
    c.spoil(s);
    EXPECT_EQ(s.write(), FT_ERR_INVALID_ARGUMENT) << c.what;
    EXPECT_NE(std::string(ft_last_error()).find(c.what), std::string::npos) << ft_last_error();
    EXPECT_FALSE(fs::exists(s.t / "b.pov")) << c.what;
  }
}

}  // namespace
