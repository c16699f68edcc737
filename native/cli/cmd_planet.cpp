// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra planet: a fractal planet (fBm or midpoint) as a cube-sphere (one
// raster per face plus a manifest, or a closed mesh), a patch of one face at
// any level, an equirectangular map (georeferenced in EPSG:4326 when written
// as GeoTIFF) or an icosphere mesh; --spectrum adds its spherical-harmonic
// power spectrum and H to --stats.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "io/obj_io.hpp"
#include "io/ply_io.hpp"
#include "planet/cube_sphere.hpp"
#include "planet/equirect.hpp"
#include "planet/icosphere.hpp"
#include "planet/sphere_spectrum.hpp"
#include "planet/planet_params.hpp"
#include "povray/planet_scene.hpp"
#include "povray/render.hpp"

namespace ft::cli::cmd_planet {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFaceNames[6] = {"px", "nx", "py", "ny", "pz", "nz"};

struct PlanetCli {
  std::string layout = "cube", size = "2048x1024", patch, out, format = ".tif", pov, render, spectrum,
      pov_geometry = "isosurface";
  pov::PlanetScene scene;
  pov::RenderOptions r;
  int level = 6;
  double vertical_scale = 1.0;
  bool stats = false;
  ft_planet_params flags = defaults_of<ft_planet_params>(planet::planet_param_table());
};

struct Patch {
  int face = 0;
  long long x0 = 0, y0 = 0;
  int w = 0, h = 0;
};

Patch parse_patch(const std::string& text) {
  Patch p;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d,%lld,%lld,%d,%d%c", &p.face, &p.x0, &p.y0, &p.w, &p.h, &extra) != 5)
    invalid("--patch must be FACE,X0,Y0,W,H (face 0..5: +X -X +Y -Y +Z -Z; e.g. 4,0,0,1025,1025), got '" + text +
            "'");
  return p;
}

void parse_wxh(const std::string& text, int* w, int* h) {
  char x = 0, extra = 0;
  const int got = std::sscanf(text.c_str(), "%d%c%d%c", w, &x, h, &extra);
  if (got == 1) *h = *w / 2;
  else if (!(got == 3 && (x == 'x' || x == 'X')))
    invalid("--size must be WxH (e.g. 4096x2048) or W (height W/2), got '" + text + "'");
}

// The extension as given (".ply"), read through the platform layer: --out is UTF-8.
std::string extension(const std::string& path) { return platform::utf8_of(platform::fs_path(path).extension()); }

nlohmann::json stats_json(const Heightfield& hf) {
  const HeightStats s = hf.stats();
  return {{"width", hf.width()}, {"height", hf.height()}, {"min", s.min}, {"max", s.max}, {"mean", s.mean},
          {"std", s.std}};
}

// --spectrum LMIN,LMAX: C_l up to LMAX and H fitted over LMIN..LMAX.
nlohmann::json spectrum_json(const planet::Planet& planet, const std::string& text) {
  int lo = 0, hi = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d,%d%c", &lo, &hi, &extra) != 2)
    invalid("--spectrum must be LMIN,LMAX (e.g. 8,64), got '" + text + "'");
  check_int_range("--spectrum LMAX", hi, 2, planet::kMaxSpectrumDegree);
  check_int_range("--spectrum LMIN", lo, 1, hi - 1);
  Stopwatch clock;
  const std::vector<double> power = planet::angular_power_spectrum(planet, hi);
  const planet::SpectrumHurst fit = planet::spectrum_hurst(power, lo, hi);
  return {{"l_min", lo}, {"l_max", hi}, {"hurst", fit.hurst}, {"std_error", fit.std_error}, {"slope", fit.slope},
          {"seconds", clock.seconds()}, {"power", power}};
}

void write_mesh(const Mesh& mesh, const std::string& out, const std::string& what, nlohmann::json* info) {
  (*info)["vertices"] = mesh.vertex_count();
  (*info)["faces"] = mesh.face_count();
  if (out.empty()) return;
  const std::string ext = extension(out), comment = "fracterra planet, " + what + ", metres";
  if (ext == ".ply") io::write_ply(mesh, out, comment);
  else if (ext == ".obj") io::write_obj(mesh, out, comment);
  else invalid("a mesh's --out is a .ply or .obj file, got '" + out + "'");
}

void write_json(const nlohmann::json& j, const std::string& path) {
  io::AtomicFile f(path);
  f.write(j.dump(2) + "\n");
  f.commit();
}

int run(const CLI::App& app, const PlanetCli& o) {
  if (o.out.empty() && !o.stats && o.pov.empty()) invalid("give --out DIR|FILE, --pov SCENE and/or --stats");
  if (!o.spectrum.empty() && !o.stats) invalid("--spectrum adds to --stats: give --stats too");
  if (!o.render.empty() && o.pov.empty()) invalid("--render needs --pov SCENE (the scene it renders)");
  ft_planet_params p = o.flags;
  const bool level_given = flag_given(app, "sea_level"), fraction_given = flag_given(app, "sea_fraction");
  if (level_given && fraction_given) invalid("give --sea-level H or --sea-fraction F, not both");
  if (!flag_given(app, "sea")) {
    if (level_given) p.sea = FT_PLANET_SEA_HEIGHT;
    if (fraction_given) p.sea = FT_PLANET_SEA_FRACTION;
  }
  const planet::PlanetConfig config = planet::from_c(p);
  Stopwatch clock;
  nlohmann::json info = {{"method", config.method == planet::kMethodMidpoint ? "midpoint" : "fbm"},
                         {"radius", config.radius}, {"seed", config.fbm.seed}};
  if (config.method == planet::kMethodFbm) info["octaves"] = config.fbm.octaves;
  auto render_if_asked = [&] {
    if (o.render.empty()) return;
    Stopwatch render_clock;
    pov::render_scene(o.pov, o.render, o.r);
    info["render_seconds"] = render_clock.seconds();
  };
  if (o.layout != "cube" && o.layout != "equirect" && o.layout != "icosphere")
    invalid("--layout must be cube, equirect or icosphere, got '" + o.layout + "'");
  if (!o.spectrum.empty()) info["spectrum"] = spectrum_json(planet::Planet(config), o.spectrum);
  if (o.layout == "icosphere" && o.patch.empty() && o.pov.empty()) {
    check_int_range("--level", o.level, 0, planet::kMaxIcosphereLevel);
    const planet::Planet planet(config);
    const Mesh mesh = planet::icosphere_mesh(planet, o.level, o.vertical_scale);
    info["seconds"] = clock.seconds();
    write_mesh(mesh, o.out, "icosphere level " + std::to_string(o.level), &info);
    if (!std::isnan(planet.sea_height())) info["sea_height"] = planet.sea_height();
  } else if (!o.patch.empty()) {
    const Patch q = parse_patch(o.patch);
    planet::validate_patch(o.level, q.face, q.x0, q.y0, q.w, q.h);
    const planet::Planet planet(config);
    const Heightfield hf = planet::face_patch(planet, o.level, q.face, q.x0, q.y0, q.w, q.h);
    info["seconds"] = clock.seconds();
    info["patch"] = stats_json(hf);
    if (!o.out.empty()) io::write_heightfield(hf, o.out);
  } else if (!o.pov.empty() && o.pov_geometry == "mesh2") {
    // The exact cube-sphere of --level, heights times the scene's exaggeration.
    if (!o.out.empty())
      invalid("--pov-geometry mesh2 writes the mesh beside the scene; write --out with another command");
    const planet::Planet planet(config);
    std::vector<float> heights;
    const Mesh mesh = planet::cube_sphere_mesh(planet, o.level, o.scene.exaggeration, &heights);
    info["seconds"] = clock.seconds();
    info["vertices"] = mesh.vertex_count();
    pov::PlanetScene scene = o.scene;
    scene.radius = config.radius;
    scene.sea_height = planet.sea_height();
    pov::write_planet_mesh_scene(mesh, heights, scene, o.pov);
    render_if_asked();
    if (!std::isnan(planet.sea_height())) info["sea_height"] = planet.sea_height();
  } else if (o.layout == "equirect" || !o.pov.empty()) {
    int w = 0, h = 0;
    parse_wxh(o.size, &w, &h);
    check_int_range("--size width", w, 2, 65536);
    check_int_range("--size height", h, 2, 65536);
    const planet::Planet planet(config);
    const Heightfield hf = planet::equirect(planet, w, h);
    info["seconds"] = clock.seconds();
    info["map"] = stats_json(hf);
    if (!o.out.empty()) io::write_heightfield(hf, o.out);
    if (!o.pov.empty()) {
      pov::PlanetScene scene = o.scene;
      scene.radius = config.radius;
      scene.sea_height = planet.sea_height();
      pov::write_planet_scene(hf, scene, o.pov);
      render_if_asked();
    }
    if (!std::isnan(planet.sea_height())) info["sea_height"] = planet.sea_height();
  } else {
    const std::string ext = extension(o.out);
    const planet::Planet planet(config);
    if (ext == ".ply" || ext == ".obj") {
      const Mesh mesh = planet::cube_sphere_mesh(planet, o.level, o.vertical_scale);
      info["seconds"] = clock.seconds();
      write_mesh(mesh, o.out, "level " + std::to_string(o.level), &info);
    } else {
      if (!ext.empty() && !fs::is_directory(platform::fs_path(o.out)))
        invalid("a cube layout's --out is a folder (one raster per face plus planet.json) or a .ply or .obj "
                "mesh, got '" + o.out + "'");
      planet::validate_patch(o.level, 0, 0, 0, (int64_t(1) << o.level) + 1, (int64_t(1) << o.level) + 1);
      if (!o.out.empty()) fs::create_directories(platform::fs_path(o.out));
      nlohmann::json faces = nlohmann::json::array();
      const int32_t side = int32_t((int64_t(1) << o.level) + 1);
      for (int f = 0; f < 6; ++f) {
        const Heightfield hf = planet::face_patch(planet, o.level, f, 0, 0, side, side);
        nlohmann::json face = stats_json(hf);
        face["face"] = f;
        face["name"] = kFaceNames[f];
        if (!o.out.empty()) {
          const std::string name = std::string("face_") + kFaceNames[f] + o.format;
          io::write_heightfield(hf, platform::join_path(o.out, name));
          face["file"] = name;
        }
        faces.push_back(face);
      }
      info["seconds"] = clock.seconds();
      info["faces"] = faces;
      if (!o.out.empty()) {
        nlohmann::json manifest = {
            {"format", "fracterra planet cube-sphere"},
            {"convention", "OpenGL cube map; fracterra/planet.h: face f sample (i, j) at the integer cube point "
                           "N n_f + (2i - N) s_f + (2j - N) t_f, N = 2^level, normalised"},
            {"level", o.level}, {"samples_per_side", side}, {"radius", config.radius},
            {"units", "metres above the radius"}, {"faces", faces}};
        if (!std::isnan(planet.sea_height())) manifest["sea_height"] = planet.sea_height();
        manifest["params"] = {{"method", info["method"]}, {"seed", config.fbm.seed}, {"octaves", config.fbm.octaves},
                              {"hurst", config.fbm.hurst}, {"sigma", config.fbm.sigma},
                              {"frequency", config.fbm.frequency}, {"lacunarity", config.fbm.lacunarity},
                              {"basis", config.fbm.basis}, {"variant", config.fbm.variant}};
        write_json(manifest, platform::join_path(o.out, "planet.json"));
      }
    }
    if (!std::isnan(planet.sea_height())) info["sea_height"] = planet.sea_height();
  }
  if (o.stats) std::printf("%s\n", info.dump().c_str());
  return 0;
}

Registration reg({"planet",
                  "A fractal planet (fBm or midpoint): cube-sphere faces or mesh, a face patch, an equirectangular "
                  "map or an icosphere",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<PlanetCli>();
                    app.add_option("--layout", o->layout,
                                   "cube (six faces, or a mesh), equirect, or icosphere (a .ply / .obj mesh)")
                        ->capture_default_str();
                    app.add_option("--level", o->level,
                                   "cube-face level n: faces of (2^n + 1)^2 samples (patches up to 26, meshes up "
                                   "to 12); icosphere: 10 4^n + 2 vertices (up to 10)")
                        ->capture_default_str();
                    app.add_option("--spectrum", o->spectrum,
                                   "LMIN,LMAX: add the spherical-harmonic power spectrum C_l (l <= LMAX <= 512) "
                                   "and H fitted to C_l ~ l^-(2H+2) over LMIN..LMAX to --stats (e.g. 8,64)");
                    app.add_option("--size", o->size, "equirectangular map WxH")->capture_default_str();
                    app.add_option("--patch", o->patch,
                                   "FACE,X0,Y0,W,H: W x H samples of one face (0..5: +X -X +Y -Y +Z -Z) from "
                                   "(X0, Y0) at --level");
                    app.add_option("--out", o->out,
                                   "cube: a folder (one raster per face + planet.json) or a .ply / .obj mesh; "
                                   "patch and equirect: a raster (.tif georeferenced for equirect, .exr, ...)");
                    app.add_option("--format", o->format, "the faces' raster extension in a cube folder")
                        ->capture_default_str();
                    app.add_option("--vertical-scale", o->vertical_scale, "mesh heights' exaggeration")
                        ->capture_default_str();
                    app.add_flag("--stats", o->stats, "print a JSON object: sizes, heights, seconds");
                    app.add_option("--pov", o->pov,
                                   "write a POV-Ray scene of the globe (isosurface over the equirectangular map "
                                   "of --size, saved beside it as <scene>_height.png)");
                    app.add_option("--pov-geometry", o->pov_geometry,
                                   "the scene's ground: isosurface (over the map of --size) or mesh2 (the exact "
                                   "cube-sphere of --level, as <scene>_mesh.inc)")
                        ->check(CLI::IsMember({"isosurface", "mesh2"}))
                        ->capture_default_str();
                    app.add_option("--render", o->render, "also render the scene with povray to this PNG");
                    app.add_option("--exaggeration", o->scene.exaggeration, "the scene's height exaggeration")
                        ->capture_default_str();
                    app.add_option("--view-latitude", o->scene.view_latitude_deg, "the point the camera faces")
                        ->capture_default_str();
                    app.add_option("--view-longitude", o->scene.view_longitude_deg, "the point the camera faces")
                        ->capture_default_str();
                    app.add_option("--width", o->r.width, "render width in pixels")->check(CLI::Range(1, 16384))
                        ->capture_default_str();
                    app.add_option("--height", o->r.height, "render height in pixels")->check(CLI::Range(1, 16384))
                        ->capture_default_str();
                    add_param_flags(app, planet::planet_param_table(), &o->flags);
                    return [o, &app] { return run(app, *o); };
                  },
                  17});

}  // namespace
}  // namespace ft::cli::cmd_planet
