// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra rivers: the rivers, lakes and sea of a heightfield as polylines
// and polygons (CSV, JSON, GeoJSON, GeoPackage), the terrain carved along
// them, and the network's measures.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/network_json.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "hydrology/hydrology.hpp"
#include "hydrology/hydrology_params.hpp"
#include "hydrology/network_measures.hpp"
#include "hydrology/river_files.hpp"
#include "io/heightfield_io.hpp"
#include "tiles/tileset_reader.hpp"

namespace ft::cli {

nlohmann::json network_json(const hydrology::NetworkMeasures& m) {
  nlohmann::json j = {{"segments", m.segments},
                      {"vertices", m.vertices},
                      {"lakes", m.lakes},
                      {"total_length", m.total_length},
                      {"land_area", m.land_area},
                      {"drainage_density", m.drainage_density},
                      {"hack_h", m.hack_h},
                      {"hack_h_stderr", m.hack_h_stderr},
                      {"ends", {{"confluence", m.ends[0]}, {"sea", m.ends[1]}, {"lake", m.ends[2]},
                                {"edge", m.ends[3]}, {"sink", m.ends[4]}}}};
  if (m.has_horton) {
    j["strahler_orders"] = m.horton.orders;
    j["streams_per_order"] = m.horton.streams;
    j["mean_length_per_order"] = m.horton.mean_length;
    j["bifurcation_ratio"] = m.horton.bifurcation;
    j["length_ratio"] = m.horton.length;
    j["horton_fitted_orders"] = m.horton.fitted_orders;
  }
  return j;
}

void sea_from_flags(const CLI::App& app, ft_hydrology_params& p) {
  const bool level = flag_given(app, "sea_level"), fraction = flag_given(app, "sea_fraction");
  if (level && fraction) invalid("give --sea-level H or --sea-fraction F, not both");
  if (!flag_given(app, "sea")) {
    if (level) p.sea = FT_WATER_SEA_HEIGHT;
    if (fraction) p.sea = FT_WATER_SEA_FRACTION;
  }
}

namespace cmd_rivers {
namespace {

struct RiversCli {
  std::string in, tiles, out, lakes, carve;
  int32_t lod = 0;
  double world_size = 0;
  bool stats = false;
  ft_hydrology_params flags = defaults_of<ft_hydrology_params>(hydrology::hydrology_param_table());
};

Registration reg({"rivers", "Rivers, lakes and the sea of a heightfield, as polylines and polygons",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<RiversCli>();
                    app.add_option("--in", o->in, "heightfield (any format `terrain` writes or GDAL reads)")
                        ->check(existing_file);
                    app.add_option("--tiles", o->tiles,
                                   "a finished tile set's folder (fracterra tiles) instead of --in: one network "
                                   "across its tiles, in the set's map coordinates (a float tiff set: the rivers "
                                   "of the whole terrain exactly); the set is read whole at --lod");
                    app.add_option("--lod", o->lod,
                                   "--tiles: the level of detail the set is read at (every 2^lod-th sample)")
                        ->capture_default_str();
                    app.add_option("--out", o->out,
                                   "rivers: .csv or .json (the polyline format with discharge, width, depth, "
                                   "order), .geojson (LineStrings) or .gpkg (rivers and lakes layers)");
                    app.add_option("--lakes", o->lakes, "lakes as .geojson or .gpkg Polygons, or .json");
                    app.add_option("--carve", o->carve, "the terrain lowered along the rivers (a heightfield)");
                    app.add_option("--world-size", o->world_size,
                                   "extent along x in world units when the file does not record it [default: 10]");
                    app.add_flag("--stats", o->stats,
                                 "print a JSON object: segments, lakes, total length, drainage density, Strahler "
                                 "orders, Horton's ratios, Hack's h");
                    add_param_flags(app, hydrology::hydrology_param_table(), &o->flags);
                    return [o, &app] {
                      if (o->out.empty() && o->lakes.empty() && o->carve.empty() && !o->stats)
                        invalid("give --out FILE, --lakes FILE, --carve FILE and/or --stats");
                      if (o->in.empty() == o->tiles.empty()) invalid("give --in FILE or --tiles DIR");
                      ft_hydrology_params p = o->flags;
                      sea_from_flags(app, p);
                      Heightfield hf = o->tiles.empty() ? io::read_heightfield(o->in) : tiles::read_tileset_whole(o->tiles, o->lod);
                      settle_world_size(hf, o->world_size, o->in.empty() ? o->tiles : o->in);
                      const hydrology::HydrologyConfig c = hydrology::from_c(p);
                      Stopwatch clock;
                      const hydrology::RiverNetwork net = hydrology::extract_rivers(hf, c);
                      const double seconds = clock.seconds();
                      if (!o->out.empty()) hydrology::write_rivers(net, hf.georef(), o->out);
                      if (!o->lakes.empty()) hydrology::write_lakes(net, hf.georef(), o->lakes);
                      if (!o->carve.empty()) io::write_heightfield(hydrology::carve(hf, net), o->carve);
                      if (o->stats) {
                        nlohmann::json j = network_json(hydrology::measure_network(net));
                        j["seconds"] = seconds;
                        std::printf("%s\n", j.dump().c_str());
                      }
                      return 0;
                    };
                  },
                  16});

}  // namespace
}  // namespace cmd_rivers
}  // namespace ft::cli
