// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra scene: a terrain and polylines as one POV-Ray scene.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "cli/splat_sources.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/heightfield_io.hpp"
#include "hydrology/river_files.hpp"
#include "io/polyline_io.hpp"
#include "povray/pov_params.hpp"
#include "povray/render.hpp"
#include "povray/scene.hpp"
#include "tiles/manifest.hpp"
#include "tiles/mosaic_vrt.hpp"

namespace ft::cli::cmd_scene {
namespace {

const std::map<std::string, int> kKinds = {{"line", int(pov::LineKind::kGeneric)},
                                           {"lightning", int(pov::LineKind::kLightning)},
                                           {"coastline", int(pov::LineKind::kCoastline)}};

struct SceneOptions {
  std::string terrain, tiles, pov, render, rivers, rules, maps, texture = "splat";
  std::vector<std::string> polylines;
  std::vector<int> kinds;
  std::vector<double> radii, radius_scales;
  bool radius_from_file = false;
  double size = 0, vertical_scale = 0, sea_fraction = NAN, water = NAN;
  // Camera and sun from ft_pov_scene_params' table, the sweeps' spline,
  // segments and tolerance from ft_pov_sweep_params'; the terrain's extent,
  // scale and sea, and the radii per line set, have their own forms here.
  ft_pov_scene_params scene = defaults_of<ft_pov_scene_params>(pov::scene_param_table());
  ft_pov_sweep_params sweep = defaults_of<ft_pov_sweep_params>(pov::sweep_param_table());
  bool aspect_given = false;
  pov::RenderOptions r;
};

// A finished 16-bit tile set as height_fields edge to edge, framed on a
// coarse preview of the whole read through its VRT overviews.
pov::TiledTerrain load_tiles(const std::string& dir) {
  const std::optional<nlohmann::json> m = tiles::read_manifest(dir);
  if (!m) invalid("'" + dir + "' holds no tile set (no manifest.json); write one with fracterra tiles");
  if (!m->value("complete", false)) invalid("the tile set in '" + dir + "' is not finished; rerun fracterra tiles to resume it");
  if (m->value("tile_format", "") != "png16")
    invalid("POV-Ray height_fields read PNG: write the tile set with --format png16");
  pov::TiledTerrain t;
  t.spacing = (*m)["sample_spacing"].get<double>();
  t.height_min = (*m)["height_range"]["min"].get<double>();
  t.height_max = (*m)["height_range"]["max"].get<double>();
  for (const nlohmann::json& e : (*m)["tiles"])
    t.tiles.push_back({platform::utf8_of(platform::fs_path(dir) / platform::fs_path(e["file"].get<std::string>())), e["x0"].get<int64_t>(),
                       e["y0"].get<int64_t>(), e["width"].get<int32_t>(), e["height"].get<int32_t>()});
  return t;
}

// The terrain's colours by the splat rules (the built-in ones or --rules, with
// the erosion --maps if given), linear RGB per sample: the colour map
// `fracterra splat --color` bakes and the Blender material shows. The slopes
// are the file's own, as `fracterra splat` reads them: its recorded world
// size, else --size, else 10.
std::vector<float> splat_colors(const SceneOptions& o, Heightfield& hf) {
  const SplatSources src = read_splat_sources(o.rules, o.maps);
  // The rules' world size for this call only: the rivers below read the recorded one.
  const double recorded = hf.world_size();
  if (recorded <= 0) hf.set_world_size(o.size > 0 ? o.size : 10.0);
  struct Restore {
    Heightfield& hf;
    double size;
    ~Restore() { hf.set_world_size(size); }
  } restore{hf, recorded};
  return splat::splat_colors_linear(src.inputs(hf), src.rules.layers.data(), src.layer_count());
}

int run(SceneOptions& o) {
  pov::SceneParams p;
  // Checked against the tables first, then the terrain's own forms (which set world sizes and sea) follow.
  if (!o.render.empty() && !o.aspect_given) o.scene.camera_aspect = double(o.r.width) / double(o.r.height);
  pov::apply_scene_settings(o.scene, p);
  p.sweep = pov::sweep_options(o.sweep);
  Heightfield hf;
  std::vector<float> colors;  // the terrain's, alive until the scene is written
  pov::TiledTerrain tiled;
  std::vector<PolylineSet> sets(o.polylines.size());
  if (!o.tiles.empty()) {
    if (!o.terrain.empty()) invalid("give --terrain or --tiles, not both");
    if (!o.rules.empty() || !o.maps.empty())
      invalid("--rules and --maps colour a --terrain; a tile set is textured by altitude and slope");
    if (!std::isnan(o.sea_fraction) && !std::isnan(o.water)) invalid("give --sea-fraction or --water, not both");
    tiled = load_tiles(o.tiles);
    hf = tiles::read_mosaic_preview(o.tiles, 257);
    // Heights in the set's own units unless --vertical-scale says otherwise.
    pov::set_scene_terrain(p, hf, hf.world_size(), o.vertical_scale > 0 ? o.vertical_scale : 1.0, o.sea_fraction);
    if (!std::isnan(o.water)) p.has_sea = true, p.sea_level = o.water;
    p.tiles = &tiled;
  } else if (!o.terrain.empty()) {
    hf = io::read_heightfield(o.terrain);
    if (!std::isnan(o.sea_fraction) && !std::isnan(o.water)) invalid("give --sea-fraction or --water, not both");
    // The terrain's own world size (recorded by fracterra) unless --size says otherwise.
    const double size = o.size > 0 ? o.size : hf.world_size() > 0 ? hf.world_size() : 1.0;
    pov::set_scene_terrain(p, hf, size, o.vertical_scale, o.sea_fraction);
    if (!std::isnan(o.water)) p.has_sea = true, p.sea_level = o.water;
    if (o.texture == "splat") {
      colors = splat_colors(o, hf);
      p.terrain_colors = colors.data();
    }
  } else if (!std::isnan(o.water)) {
    p.has_sea = true, p.sea_level = o.water;
  }
  if (o.kinds.size() > o.polylines.size()) invalid("more --kind options than --polyline files");
  if (o.radii.size() > o.polylines.size()) invalid("more --radius options than --polyline files");
  if (o.radius_scales.size() > o.polylines.size()) invalid("more --radius-scale options than --polyline files");
  for (size_t i = 0; i < o.polylines.size(); ++i) {
    sets[i] = io::read_polylines(o.polylines[i]);
    pov::SceneLines l;
    l.set = &sets[i];
    l.kind = pov::LineKind(i < o.kinds.size() ? o.kinds[i] : int(pov::LineKind::kGeneric));
    l.radius = i < o.radii.size() ? o.radii[i] : 0.0;
    l.radius_scale = i < o.radius_scales.size() ? o.radius_scales[i] : 1.0;
    l.radii_in_world_units = o.radius_from_file;
    p.lines.push_back(l);
  }
  hydrology::WaterScene water;
  if (!o.rivers.empty()) {
    if (o.terrain.empty()) invalid("--rivers needs the --terrain they were traced on");
    water = hydrology::read_water_json(o.rivers);
    // `fracterra rivers` worked in the terrain's recorded world size (10
    // when it records none); the scene may place it at another --size and
    // scales its heights by the vertical scale.
    const double k = p.world_size_x / (hf.world_size() > 0 ? hf.world_size() : 10.0);
    for (Vec3& q : water.rivers.points) q = {q[0] * k, q[1] * k, q[2] * p.vertical_scale};
    for (double& r : water.rivers.radii) r *= k;
    p.rivers = &water.rivers;
    for (const auto& lake : water.lakes) {
      pov::SceneLake l{lake.level * p.vertical_scale, {}};
      for (const auto& ring : lake.rings) {
        l.rings.emplace_back();
        for (const Vec3& q : ring) l.rings.back().push_back({q[0] * k, q[1] * k, l.level});
      }
      p.lakes.push_back(std::move(l));
    }
  }
  p.image_width = o.r.width;
  p.title = !o.tiles.empty() ? "tile set " + o.tiles : o.terrain.empty() ? "polylines" : "terrain " + o.terrain;
  const auto sum = pov::write_scene(p, o.pov);
  std::printf("wrote %s%s%s\n", o.pov.c_str(), sum.image_path.empty() ? "" : " and ", sum.image_path.c_str());
  if (!o.render.empty()) {
    Stopwatch clock;
    const auto res = pov::render_scene(o.pov, o.render, o.r);
    if (res.warnings > 0) std::fputs(res.messages.c_str(), stderr);
    std::printf("rendered %s (%dx%d) in %.2f s\n", o.render.c_str(), o.r.width, o.r.height, clock.seconds());
  }
  return 0;
}

Registration reg({"scene", "Write a POV-Ray scene of a terrain and polylines (and render it)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<SceneOptions>();
                    app.add_option("--terrain", o->terrain, io::kHeightfieldReadHelp)->check(existing_file);
                    app.add_option("--tiles", o->tiles,
                                   "a finished 16-bit tile set folder (fracterra tiles --format png16): its tiles "
                                   "as height_fields edge to edge, in the set's world size")
                        ->check(existing_directory);
                    app.add_option("--polyline", o->polylines, "polyline set .csv or .json (world units); repeatable")
                        ->check(existing_file);
                    app.add_option("--kind", o->kinds,
                                   "kind of the polyline set at the same position: line, lightning (glowing) or "
                                   "coastline (thin, on the sea); default line")
                        ->transform(choice(kKinds));
                    app.add_option("--radius", o->radii,
                                   "tube radius (world units) of the polyline set at the same position, overriding "
                                   "the radii in its file (they keep only its taper); 0 = automatic (default): "
                                   "0.75 pixel at --width, or a tenth of the median segment, capped by kind")
                        ->check(CLI::NonNegativeNumber);
                    app.add_option("--radius-scale", o->radius_scales,
                                   "multiplies every radius of the polyline set at the same position (> 0; default 1)")
                        ->check(CLI::PositiveNumber);
                    app.add_flag("--radius-from-file", o->radius_from_file,
                                 "take the radii stored in the polyline files as world units (vertices with 0 get "
                                 "--radius or the automatic one)");
                    app.add_option("--rivers", o->rivers,
                                   "rivers and lakes (.json of fracterra rivers, on this --terrain): rivers as "
                                   "water ribbons as wide as the rivers, lakes as water at their levels")
                        ->check(existing_file);
                    app.add_option("--texture", o->texture,
                                   "how the --terrain is coloured: splat (the splat rules' colour map, as "
                                   "fracterra splat --color bakes it and the Blender material shows it) or "
                                   "altitude (ft_terrain.inc's sand, grass, rock and snow by altitude and slope; "
                                   "tile sets always) [default: splat]")
                        ->check(CLI::IsMember({"splat", "altitude"}));
                    app.add_option("--rules", o->rules,
                                   "splat rules JSON that colour the terrain (as fracterra splat --rules reads "
                                   "them) [default: grass, rock, sediment, snow]")
                        ->check(existing_file);
                    app.add_option("--maps", o->maps,
                                   "the folder of fracterra erode --maps for the rules' deposit and flow "
                                   "conditions (without it they see none)")
                        ->check(existing_directory);
                    app.add_option("--pov", o->pov, "scene to write (.pov); the terrain PNG goes beside it")->required();
                    app.add_option("--size", o->size,
                                   "terrain width in world units (x); depth follows the grid; default: the world "
                                   "size recorded in the terrain file, else 1")
                        ->check(CLI::NonNegativeNumber);
                    app.add_option("--vertical-scale", o->vertical_scale,
                                   "height multiplier; 0 = relief of 20% of --size")
                        ->check(CLI::NonNegativeNumber)->capture_default_str();
                    app.add_option("--sea-fraction", o->sea_fraction,
                                   "sea level at this fraction of the terrain's samples (0..0.999); default no sea")
                        ->check(CLI::Range(0.0, 0.999));
                    app.add_option("--water", o->water, "sea level in world units (instead of --sea-fraction)");
                    // The names these flags had before the table stay as aliases.
                    add_param_flags(app, pov::scene_param_table(), &o->scene,
                                    {"world_size_x", "world_size_y", "vertical_scale", "has_sea", "sea_level"},
                                    {{"camera_azimuth_deg", "--azimuth"},
                                     {"camera_elevation_deg", "--elevation"},
                                     {"camera_fov_deg", "--fov"},
                                     {"camera_distance_scale", "--zoom-out"},
                                     {"sun_azimuth_deg", "--sun-azimuth"},
                                     {"sun_elevation_deg", "--sun-elevation"}});
                    add_param_flags(app, pov::sweep_param_table(), &o->sweep, {"default_radius", "radius_scale"});
                    app.add_option("--render", o->render, "also render the scene with povray to this PNG");
                    app.add_option("--width", o->r.width, "render width in pixels (also sets the framing aspect)")
                        ->check(CLI::Range(1, 16384))->capture_default_str();
                    app.add_option("--height", o->r.height, "render height in pixels")->check(CLI::Range(1, 16384))
                        ->capture_default_str();
                    app.add_option("--antialias", o->r.antialias, "anti-aliasing threshold (povray +A), 0 = off")
                        ->check(CLI::Range(0.0, 3.0))->capture_default_str();
                    auto* aspect = app.get_option("--camera-aspect");
                    // The camera elevation's default is auto: the library picks it by what the scene holds.
                    return [o, aspect] {
                      o->aspect_given = aspect->count() > 0;
                      if (o->terrain.empty() && o->tiles.empty() && o->polylines.empty())
                        invalid("give --terrain or --tiles and/or --polyline");
                      if (o->texture == "altitude" && (!o->rules.empty() || !o->maps.empty()))
                        invalid("--rules and --maps set the splat colours: drop them or --texture altitude");
                      return run(*o);
                    };
                  },
                  80});

}  // namespace
}  // namespace ft::cli::cmd_scene
