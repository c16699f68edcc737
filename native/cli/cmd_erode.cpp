// fracterra erode: fluvial, hydraulic and thermal erosion of a heightfield,
// and the maps (drainage area, slope, curvature, water, eroded, deposited).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "io/heightfield_io.hpp"

namespace ft::cli {
namespace {

struct ErodeCli {
  std::string in, out, maps, preset;
  double world_size = 0;
  bool stats = false;
  erosion::ErosionConfig c;
};

void add_erosion_options(CLI::App& app, erosion::ErosionConfig& c) {
  auto& f = c.fluvial;
  app.add_option("--fluvial", f.steps, "fluvial (stream power + diffusion) time steps, 0 = off")->capture_default_str();
  app.add_option("--fluvial-dt", f.dt, "years per fluvial step (> 0)")->capture_default_str();
  app.add_option("--erodibility", f.k, "stream-power K (>= 0)")->capture_default_str();
  app.add_option("--area-exponent", f.m, "stream-power m, 0..2 (n = 1)")->capture_default_str();
  app.add_option("--diffusion", f.diffusion, "hillslope diffusivity, world units^2 per year (>= 0)")
      ->capture_default_str();
  app.add_option("--uplift", f.uplift, "uplift, world units per year (>= 0)")->capture_default_str();
  auto& h = c.hydraulic;
  app.add_option("--hydraulic", h.iterations, "hydraulic (virtual-pipe water) passes, 0 = off")->capture_default_str();
  app.add_option("--hydraulic-dt", h.dt, "seconds per hydraulic pass, 1e-6..1")->capture_default_str();
  app.add_option("--rain", h.rain, "water depth rained per pass, world units (>= 0)")->capture_default_str();
  app.add_option("--evaporation", h.evaporation, "fraction of the water evaporated per pass, 0..1")
      ->capture_default_str();
  app.add_option("--capacity", h.capacity, "sediment capacity constant (>= 0)")->capture_default_str();
  app.add_option("--dissolve", h.dissolve, "fraction of the capacity deficit eroded per pass, 0..1")
      ->capture_default_str();
  app.add_option("--deposit", h.deposit, "fraction of the excess sediment deposited per pass, 0..1")
      ->capture_default_str();
  auto& t = c.thermal;
  app.add_option("--thermal", t.iterations, "thermal (talus) passes, 0 = off")->capture_default_str();
  app.add_option("--talus", t.talus_degrees, "angle of repose in degrees, 0..89")->capture_default_str();
  app.add_option("--thermal-rate", t.rate, "fraction of the excess moved per pass, (0, 1]")->capture_default_str();
  app.add_flag("--periodic", c.periodic, "the terrain tiles: erode it as a torus (stays seamless)");
  app.add_option("--threads", c.threads, "worker threads, 0 = all cores (output never depends on it)")
      ->check(CLI::Range(0, 1024))->capture_default_str();
}

Registration reg({"erode", "Erode a heightfield (fluvial, hydraulic, thermal) and write its maps",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<ErodeCli>();
                    app.add_option("--in", o->in, "heightfield .png, .pgm or .npy")->required()->check(CLI::ExistingFile);
                    app.add_option("--out", o->out, "eroded heightfield .png, .pgm or .npy");
                    app.add_option("--maps", o->maps,
                                   "folder for the maps as 16-bit PNGs with their ranges (and maps.json)");
                    app.add_option("--preset", o->preset,
                                   "start from a preset: valleys, rain, scree or land (options given override it)");
                    app.add_option("--world-size", o->world_size,
                                   "extent along x in world units when the file does not record it [default: 10]");
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, the height range before and after, what left at the edges");
                    add_erosion_options(app, o->c);
                    return [o, &app] {
                      if (o->out.empty() && o->maps.empty() && !o->stats) invalid("give --out FILE, --maps DIR and/or --stats");
                      erosion::ErosionConfig c = o->c;
                      if (!o->preset.empty()) {
                        // Options given on the command line win over the preset's.
                        erosion::ErosionConfig p = erosion::erosion_preset(o->preset);
                        if (app.count("--fluvial") == 0) c.fluvial.steps = p.fluvial.steps;
                        if (app.count("--hydraulic") == 0) c.hydraulic.iterations = p.hydraulic.iterations;
                        if (app.count("--thermal") == 0) c.thermal.iterations = p.thermal.iterations;
                      }
                      Heightfield hf = read_heightfield(o->in);
                      if (o->world_size > 0) hf.set_world_size(o->world_size);
                      else if (hf.world_size() <= 0) hf.set_world_size(10.0);
                      if (!o->maps.empty()) std::filesystem::create_directories(o->maps);
                      erosion::ErosionMaps maps;
                      erosion::MassBudget budget;
                      Stopwatch clock;
                      const Heightfield eroded = erosion::erode(hf, c, o->maps.empty() ? nullptr : &maps, &budget);
                      const double seconds = clock.seconds();
                      if (!o->out.empty()) write_heightfield(eroded, o->out);
                      if (!o->maps.empty()) erosion::write_erosion_maps(maps, o->maps);
                      if (o->stats) {
                        const HeightStats before = hf.stats(), after = eroded.stats();
                        nlohmann::json j = {{"seconds", seconds},       {"carried_out", budget.carried_out},
                                            {"min", after.min},         {"max", after.max},
                                            {"input_min", before.min},  {"input_max", before.max},
                                            {"world_size", eroded.world_size()}};
                        std::printf("%s\n", j.dump().c_str());
                      }
                      return 0;
                    };
                  },
                  15});

}  // namespace
}  // namespace ft::cli
