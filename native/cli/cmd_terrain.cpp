// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra terrain: generate a heightfield and write it as PNG/PGM/NPY.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <vector>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "contour/marching_squares.hpp"
#include "core/error.hpp"
#include "cli/engine_flags.hpp"
#include "cli/erosion_map_flags.hpp"
#include "erosion/erosion_params.hpp"
#include "hydrology/hydrology.hpp"
#include "hydrology/river_files.hpp"
#include "io/heightfield_io.hpp"
#include "io/polyline_io.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "povray/scene.hpp"
#include "terrain/mandelbrot.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::cli::cmd_terrain {
namespace {

// Erosion settings that are the terrain's here, not flags of their own: its
// threads serve every stage, a terrain that tiles erodes as a torus, and its
// landform's sea is the erosion's (the library's rules, terrain_build.cpp).
const std::set<std::string> kTerrainsOwn = {"periodic", "threads", "sea", "sea_level", "sea_fraction"};

// "--size N" (square) or "--size WxH".
void parse_size(const std::string& text, ft_terrain_params& p) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  const int got = std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra);
  if (got == 1) h = w;
  else if (!(got == 3 && (x == 'x' || x == 'X')))
    invalid("--size must be N or WxH (e.g. 1024 or 2048x1024), got '" + text + "'");
  p.width = w;
  p.height = h;
}
// "--center X,Y" (the Mandelbrot view's centre in the complex plane).
void parse_center(const std::string& text, ft_terrain_params& p) {
  double x = 0, y = 0;
  char comma = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%lf%c%lf%c", &x, &comma, &y, &extra) != 3 || comma != ',')
    invalid("--center must be X,Y (e.g. -0.745,0.11), got '" + text + "'");
  p.center_x = x;
  p.center_y = y;
}

struct TerrainOptions {
  ft_terrain_params p = terrain::default_terrain_params();
  // The pipeline's settings (a preset: --erosion-preset, or --erode) and the
  // erosion settings, both from their tables.
  ft_build_params build = defaults_of<ft_build_params>(pipeline::build_param_table());
  ft_erosion_params erosion = defaults_of<ft_erosion_params>(erosion::erosion_param_table());
  bool erosion_given = false;  // an erosion flag was given: erode with these settings
  std::string reference, falloff_mask, out, size, pov, center, curves_out, rivers;
  std::vector<double> curves;
  bool stats = false, curves_world = false;
  ErosionMapFlags erosion_maps;
  EngineFlags engine;
};

// The Mandelbrot terrain's curves of equal escape time: the contours at the
// heights those escape times map to, in columns and rows or world units.
void write_escape_curves(const TerrainOptions& o, const ft_terrain_params& p, const Heightfield& hf) {
  std::vector<double> levels;
  for (double nu : o.curves) levels.push_back(terrain::mandelbrot_height(nu, p.sigma));
  PolylineSet set = contour::marching_squares(hf, levels);
  if (o.curves_world) {
    const double k = hf.world_size() / double(hf.width() - 1);
    for (Vec3& v : set.points) v[0] *= k, v[1] *= k;
  }
  io::write_polylines(set, o.curves_out);
}

int run(TerrainOptions& o) {
  ft_terrain_params p = o.p;
  if (!o.size.empty()) parse_size(o.size, p);
  if (!o.center.empty()) parse_center(o.center, p);
  o.engine.check(o.out);
  if (o.engine.given() && !terrain::terrain_method(p.method).dyadic) {
    // Methods of any size are made at the engine's size (nothing to resample);
    // midpoint grids (2^n + 1) are resampled when the engine wants another size.
    if (o.engine.engine == "godot") {  // Terrain3D takes rectangles: each side on its own
      p.width = o.engine.generation_side(p.width);
      p.height = o.engine.generation_side(p.height);
    } else {  // Unity and Unreal take squares
      p.width = p.height = o.engine.generation_side(std::max(p.width, p.height));
    }
  }
  if (!o.curves.empty() || !o.curves_out.empty()) {
    // Refused before the work, not after it.
    if (p.method != FT_TERRAIN_MANDELBROT) invalid("--curves: curves of equal escape time need --method mandelbrot");
    if (o.curves.empty() || o.curves_out.empty()) invalid("give both --curves LIST and --curves-out FILE");
    for (double nu : o.curves) check_finite("--curves value", nu);
  }
  Heightfield reference;
  if (!o.reference.empty()) {
    reference = io::read_heightfield(o.reference);
    if (reference.width() != reference.height())
      invalid("the reference grid '" + o.reference + "' is " + std::to_string(reference.width()) + " x " +
              std::to_string(reference.height()) + "; it must be square, 2^m + 1 per side");
    p.reference = reference.data();
    p.reference_size = reference.width();
  }
  Heightfield mask;
  if (!o.falloff_mask.empty()) {
    // Any raster the project reads; 8- and 16-bit images read as 0..1 (white 1).
    mask = io::read_heightfield(o.falloff_mask);
    if (p.falloff != FT_FALLOFF_NONE && p.falloff != FT_FALLOFF_CUSTOM)
      invalid("--falloff-mask is the custom falloff's mask; it cannot go with --falloff " +
              std::string(p.falloff == FT_FALLOFF_SQUARE ? "square" : "radial"));
    p.falloff = FT_FALLOFF_CUSTOM;
    p.falloff_mask = mask.data();
    p.falloff_mask_width = mask.width();
    p.falloff_mask_height = mask.height();
  }
  Stopwatch clock;
  // Generate -> landform -> erode, the library's pipeline (as the add-on's).
  o.erosion_maps.apply(o.erosion);  // --erosion-mask, --rain-map
  ft_build_params b = o.build;
  b.terrain = &p;
  b.erosion = o.erosion_given ? &o.erosion : nullptr;
  b.threads = p.threads;
  // The rivers are the pipeline's last stage (a terrain that tiles: they wrap;
  // its own sea is theirs), with fracterra rivers' defaults.
  hydrology::RiverNetwork net;
  Heightfield hf = pipeline::build_terrain(b, nullptr, o.rivers.empty() ? nullptr : &net);
  if (!o.rivers.empty()) hydrology::write_rivers(net, hf.georef(), o.rivers);
  const double seconds = clock.seconds();
  if (!o.out.empty() && o.engine.given()) o.engine.write(hf, o.out);
  else if (!o.out.empty()) io::write_heightfield(hf, o.out);
  if (!o.pov.empty()) pov::write_terrain_scene(hf, o.pov);  // PNG beside it
  if (!o.curves_out.empty()) write_escape_curves(o, p, hf);
  if (o.stats) {
    const HeightStats s = hf.stats();
    nlohmann::json j = {{"seconds", seconds}, {"width", hf.width()}, {"height", hf.height()},
                        {"min", s.min},       {"max", s.max},        {"mean", s.mean},
                        {"std", s.std}};
    // Where the highest sample is (column, row), e.g. to place a lightning bolt.
    const float* z = hf.data();
    const size_t top = size_t(std::max_element(z, z + hf.size()) - z);
    j["peak"] = {{"column", top % size_t(hf.width())}, {"row", top / size_t(hf.width())}, {"height", z[top]}};
    if (hf.world_size() > 0) j["world_size"] = hf.world_size();
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

Registration reg({"terrain", "Generate a fractal terrain heightfield",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<TerrainOptions>();
                    auto& p = o->p;
                    add_param_flags(app, terrain::terrain_param_table(), &p, {"width", "height", "center_x", "center_y"});
                    app.add_option("--size", o->size,
                                   terrain::methods_that([](const terrain::TerrainMethod& m) { return !m.dyadic; }) +
                                       ": N (square) or WxH samples, 2..65536 per side [default: 513]");
                    app.add_option("--center", o->center,
                                   "mandelbrot: centre of the view in the complex plane, X,Y in [-4, 4] "
                                   "(row 0 is the top) [default: -0.5,0]");
                    app.add_option("--curves", o->curves,
                                   "mandelbrot: escape times whose level curves (equipotentials) to write, e.g. "
                                   "2,3,4,6,8")
                        ->delimiter(',');
                    app.add_option("--curves-out", o->curves_out,
                                   "mandelbrot: the --curves polylines as .csv or .json (x = column, y = row, z = "
                                   "height, as fracterra coastline writes them)");
                    app.add_flag("--curves-world", o->curves_world,
                                 "mandelbrot: write the curves' x, y in world units (--world-size across x)");
                    app.add_option("--reference", o->reference,
                                   "reference grid (2^m + 1)^2: " + std::string(io::kHeightfieldReadHelp) +
                                       "; its values survive exactly (a DEM: see fracterra refine)")
                        ->check(existing_file);
                    app.add_option("--falloff-mask", o->falloff_mask,
                                   "custom edge falloff (sets --falloff custom): a mask spanning the terrain, " +
                                       std::string(io::kHeightfieldReadHelp) +
                                       "; white (1) keeps the height, black (0) gives --edge-level; 8/16-bit "
                                       "images read as 0..1, other rasters must hold 0..1; resampled bilinearly, "
                                       "image row 0 (the top) at terrain row 0")
                        ->check(existing_file);
                    // The pipeline's and the erosion's settings from their tables; the
                    // terrain's threads serve every stage, and a terrain that tiles
                    // erodes as a torus (the library's rule, not a flag).
                    add_param_flags(app, pipeline::build_param_table(), &o->build, {"threads"},
                                    {{"erosion_preset", "--erode"}});
                    add_param_flags(app, erosion::erosion_param_table(), &o->erosion, kTerrainsOwn);
                    o->erosion_maps.add_to(app);
                    app.add_option("--rivers", o->rivers,
                                   "also trace its rivers and lakes (after --erode) with fracterra rivers' defaults "
                                   "and the terrain's own sea: .csv, .json, .geojson or .gpkg");
                    app.add_option("--out", o->out,
                                   "output .png (16-bit), .pgm (16-bit), .npy (float32), .tif (COG float32), "
                                   ".exr (float) or .raw/.r16 (RAW16 + sidecar .json)");
                    o->engine.add_to(app);
                    app.add_option("--pov", o->pov, "also write a POV-Ray scene (.pov, with its PNG beside it)");
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, min, max, mean, std");
                    return [o, &app] {
                      if (o->out.empty() && o->pov.empty() && o->rivers.empty() && !o->stats)
                        invalid("give --out FILE, --pov FILE, --rivers FILE and/or --stats");
                      for (const ft_param_info& row : erosion::erosion_param_table().rows)
                        if (!kTerrainsOwn.count(row.name))
                          o->erosion_given = o->erosion_given || flag_given(app, row.name);
                      return run(*o);
                    };
                  },
                  10});

}  // namespace
}  // namespace ft::cli::cmd_terrain
