// fracterra erode: fluvial, hydraulic and thermal erosion of a heightfield,
// and the maps (drainage area, slope, curvature, water, eroded, deposited).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/erosion_params.hpp"
#include "erosion/presets.hpp"
#include "io/heightfield_io.hpp"

namespace ft::cli {
namespace {

struct ErodeCli {
  std::string in, out, maps, preset;
  double world_size = 0;
  bool stats = false;
  // The settings from ft_erosion_params' table (erosion_params.cpp): what
  // the flags wrote over the table's defaults.
  ft_erosion_params flags = defaults_of<ft_erosion_params>(erosion_param_table());
};

// The flag names erode had before its flags came from the table (issue 15's
// `--fluvial 60 --hydraulic 100 --thermal 20 --talus 33`) stay as aliases.
const std::map<std::string, std::string> kAliases = {{"fluvial_steps", "--fluvial"},
                                                     {"hydraulic_iterations", "--hydraulic"},
                                                     {"thermal_iterations", "--thermal"},
                                                     {"talus_degrees", "--talus"}};

// The settings to erode `hf` with: the flags over the table's defaults, or
// over the preset fitted to the terrain when one is named (a flag given on
// the command line wins over the preset's value).
erosion::ErosionConfig settings(const ErodeCli& o, const CLI::App& app, const Heightfield& hf) {
  if (o.preset.empty()) return erosion::from_c(o.flags);
  ft_erosion_params p = erosion::to_c(erosion::erosion_preset(o.preset, hf));
  overlay_given_flags(app, erosion_param_table(), &o.flags, &p);
  return erosion::from_c(p);
}

Registration reg({"erode", "Erode a heightfield (fluvial, hydraulic, thermal) and write its maps",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<ErodeCli>();
                    app.add_option("--in", o->in, "heightfield .png, .pgm or .npy")->required()->check(CLI::ExistingFile);
                    app.add_option("--out", o->out, "eroded heightfield .png, .pgm or .npy");
                    app.add_option("--maps", o->maps,
                                   "folder for the maps as 16-bit PNGs with their ranges (and maps.json)");
                    app.add_option("--preset", o->preset,
                                   "start from a preset: valleys (fluvial with uplift), rain (hydraulic), scree "
                                   "(thermal) or land (all three); flags given override its values. Its uplift "
                                   "rate would raise the land by the terrain's relief over the preset's steps, so "
                                   "incision keeps about the relief the terrain had");
                    app.add_option("--world-size", o->world_size,
                                   "extent along x in world units when the file does not record it [default: 10]");
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, the height range before and after, what left at the edges");
                    add_param_flags(app, erosion_param_table(), &o->flags, {}, kAliases);
                    return [o, &app] {
                      if (o->out.empty() && o->maps.empty() && !o->stats) invalid("give --out FILE, --maps DIR and/or --stats");
                      if (!o->preset.empty()) erosion::erosion_preset(o->preset);  // an unknown name fails before reading
                      Heightfield hf = io::read_heightfield(o->in);
                      if (o->world_size > 0) hf.set_world_size(o->world_size);
                      else if (hf.world_size() <= 0) hf.set_world_size(10.0);
                      const erosion::ErosionConfig c = settings(*o, app, hf);
                      if (!o->maps.empty()) std::filesystem::create_directories(o->maps);
                      erosion::ErosionMaps maps;
                      erosion::MassBudget budget;
                      Stopwatch clock;
                      const Heightfield eroded = erosion::erode(hf, c, o->maps.empty() ? nullptr : &maps, &budget);
                      const double seconds = clock.seconds();
                      if (!o->out.empty()) io::write_heightfield(eroded, o->out);
                      if (!o->maps.empty()) erosion::write_erosion_maps(maps, o->maps);
                      if (o->stats) {
                        const HeightStats before = hf.stats(), after = eroded.stats();
                        nlohmann::json j = {{"seconds", seconds},       {"carried_out", budget.carried_out},
                                            {"min", after.min},         {"max", after.max},
                                            {"input_min", before.min},  {"input_max", before.max},
                                            {"uplift", c.fluvial.uplift},
                                            {"world_size", eroded.world_size()}};
                        std::printf("%s\n", j.dump().c_str());
                      }
                      return 0;
                    };
                  },
                  15});

}  // namespace
}  // namespace ft::cli
