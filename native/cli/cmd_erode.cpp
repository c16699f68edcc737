// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra erode: fluvial, hydraulic and thermal erosion of a heightfield,
// and the maps (drainage area, slope, curvature, water, eroded, deposited).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/engine_flags.hpp"
#include "cli/erosion_map_flags.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "erosion/erosion.hpp"
#include "erosion/erosion_params.hpp"
#include "erosion/presets.hpp"
#include "io/heightfield_io.hpp"
#include "pipeline/terrain_build.hpp"

namespace ft::cli::cmd_erode {
namespace {

struct ErodeCli {
  std::string in, out, maps, preset, maps_float;
  double world_size = 0;
  bool stats = false;
  ErosionMapFlags map_files;
  EngineFlags engine;
  // The settings from ft_erosion_params' table (erosion_params.cpp): what
  // the flags wrote over the table's defaults.
  ft_erosion_params flags = defaults_of<ft_erosion_params>(erosion::erosion_param_table());
};

// The flag names erode had before its flags came from the table (issue 15's
// `--fluvial 60 --hydraulic 100 --thermal 20 --talus 33`) stay as aliases.
const std::map<std::string, std::string> kAliases = {{"fluvial_steps", "--fluvial"},
                                                     {"hydraulic_iterations", "--hydraulic"},
                                                     {"thermal_iterations", "--thermal"},
                                                     {"talus_degrees", "--talus"}};

// The settings to erode `hf` with, by the pipeline's rule (the flags over
// the table's defaults, the preset fitted to `hf` over them), then the flags
// given on the command line over the preset's values, and the map files.
ft_erosion_params settings(ErodeCli& o, const CLI::App& app, const Heightfield& hf) {
  ft_erosion_params e = pipeline::erosion_settings(&o.flags, o.preset, hf);
  if (!o.preset.empty()) overlay_given_flags(app, erosion::erosion_param_table(), &o.flags, &e);
  o.map_files.apply(e);
  return e;
}

std::string preset_help() {
  std::string h = "start from a preset (flags given override its values):";
  for (const auto& p : erosion::erosion_presets())
    h += " " + p.id + (p.alias.empty() ? "" : " (old name " + p.alias + ")") + ": " + p.description + ";";
  h.back() = '.';
  return h + " Labels (\"Gentle Valleys\") work too";
}

Registration reg({"erode", "Erode a heightfield (channels, scree and fans over years; expert passes) and write its maps",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<ErodeCli>();
                    app.add_option("--in", o->in, "heightfield .png, .pgm or .npy")->required()->check(existing_file);
                    app.add_option("--out", o->out, "eroded heightfield .png, .pgm or .npy");
                    app.add_option("--maps", o->maps,
                                   "folder for the maps as 16-bit PNGs with their ranges (and maps.json; drainage "
                                   "area on a log10 scale)");
                    app.add_option("--maps-float", o->maps_float,
                                   "also write every map as float32 with its linear values: tif or exr");
                    app.add_option("--preset", o->preset, preset_help());
                    o->map_files.add_to(app);
                    o->engine.add_to(app);
                    app.add_option("--world-size", o->world_size,
                                   "extent along x in world units when the file does not record it [default: 10]");
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, the height range before and after, what left at the edges");
                    add_param_flags(app, erosion::erosion_param_table(), &o->flags, {}, kAliases);
                    return [o, &app] {
                      if (o->out.empty() && o->maps.empty() && !o->stats) invalid("give --out FILE, --maps DIR and/or --stats");
                      if (!o->preset.empty()) erosion::erosion_preset(o->preset);  // an unknown name fails before reading
                      o->engine.check(o->out);
                      Heightfield hf = io::read_heightfield(o->in);
                      settle_world_size(hf, o->world_size, o->in);
                      const ft_erosion_params e = settings(*o, app, hf);
                      if (!o->maps.empty()) std::filesystem::create_directories(platform::fs_path(o->maps));
                      erosion::ErosionMaps maps;
                      erosion::MassBudget budget;
                      Stopwatch clock;
                      // The pipeline's erode stage, as `terrain --erode` runs it (a file's
                      // grid has no repeated edge: a periodic one is a torus as it is).
                      // Godot's control map reads the maps (sediment where deposits and flow are).
                      const bool want_maps = !o->maps.empty() || o->engine.engine == "godot";
                      const Heightfield eroded =
                          pipeline::erode_terrain(hf, e, 0, want_maps ? &maps : nullptr, &budget);
                      const double seconds = clock.seconds();
                      if (!o->out.empty() && o->engine.given())
                        o->engine.write(eroded, o->out, {nullptr, want_maps ? &maps.deposited : nullptr,
                                                         want_maps ? &maps.drainage_area : nullptr});
                      else if (!o->out.empty()) io::write_heightfield(eroded, o->out);
                      if (!o->maps.empty())
                        erosion::write_erosion_maps(maps, o->maps, o->maps_float.empty() ? "" : "." + o->maps_float);
                      if (o->stats) {
                        const HeightStats before = hf.stats(), after = eroded.stats();
                        nlohmann::json j = {{"seconds", seconds},       {"carried_out", budget.carried_out},
                                            {"min", after.min},         {"max", after.max},
                                            {"input_min", before.min},  {"input_max", before.max},
                                            {"detached", budget.detached}, {"deposited", budget.deposited},
                                            {"world_size", eroded.world_size()}};
                        std::printf("%s\n", j.dump().c_str());
                      }
                      return 0;
                    };
                  },
                  15});

}  // namespace
}  // namespace ft::cli::cmd_erode
