// fracterra terrain: generate a heightfield and write it as PNG/PGM/NPY.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "povray/scene.hpp"
#include "terrain/terrain.hpp"

namespace ft::cli {
namespace {

const std::map<std::string, int> kMethods = {
    {"midpoint", FT_TERRAIN_MIDPOINT}, {"additions", FT_TERRAIN_ADDITIONS}};
const std::map<std::string, int> kRefScales = {
    {"sigma", FT_REFSCALE_SIGMA}, {"mean", FT_REFSCALE_MEAN}, {"std", FT_REFSCALE_STD}};

struct TerrainOptions {
  ft_terrain_params p = default_terrain_params();
  std::string reference, out, pov;
  bool stats = false;
};

int run(const TerrainOptions& o) {
  ft_terrain_params p = o.p;
  Heightfield reference;
  if (!o.reference.empty()) {
    reference = read_heightfield(o.reference);
    if (reference.width() != reference.height())
      invalid("the reference grid '" + o.reference + "' is " + std::to_string(reference.width()) + " x " +
              std::to_string(reference.height()) + "; it must be square, 2^m + 1 per side");
    p.reference = reference.data();
    p.reference_size = reference.width();
  }
  Stopwatch clock;
  Heightfield hf = generate_terrain(p);
  const double seconds = clock.seconds();
  if (!o.out.empty()) write_heightfield(hf, o.out);
  if (!o.pov.empty()) pov::write_terrain_scene(hf, o.pov);  // PNG beside it
  if (o.stats) {
    const HeightStats s = hf.stats();
    nlohmann::json j = {{"seconds", seconds}, {"width", hf.width()}, {"height", hf.height()},
                        {"min", s.min},       {"max", s.max},        {"mean", s.mean},
                        {"std", s.std}};
    std::printf("%s\n", j.dump().c_str());
  }
  return 0;
}

Registration reg({"terrain", "Generate a fractal terrain heightfield",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<TerrainOptions>();
                    auto& p = o->p;
                    app.add_option("--method", p.method, "terrain method")
                        ->transform(choice(kMethods))->capture_default_str();
                    app.add_option("--levels", p.levels, "refinement steps n: (2^n + 1)^2 samples")
                        ->check(CLI::Range(1, 15))->capture_default_str();
                    app.add_option("--hurst", p.hurst, "Hurst exponent H")->check(CLI::Range(0.0, 1.0))
                        ->capture_default_str();
                    app.add_option("--sigma", p.sigma, "vertical scale (> 0)")->capture_default_str();
                    app.add_option("--seed", p.seed, "random seed (64-bit)")->capture_default_str();
                    app.add_flag("--periodic", p.periodic, "tileable: wrap-around neighbours");
                    app.add_option("--reference", o->reference,
                                   "reference grid (2^m + 1)^2 as .png, .pgm or .npy; its values survive exactly")
                        ->check(CLI::ExistingFile);
                    app.add_option("--reference-scale", p.reference_scale,
                                   "displacement scale when refining references: sigma as given, or the mean "
                                   "|value| or std of the references")
                        ->transform(choice(kRefScales))->capture_default_str();
                    app.add_option("--threads", p.threads, "worker threads, 0 = all cores (output never depends on it)")
                        ->check(CLI::Range(0, 1024))->capture_default_str();
                    app.add_option("--out", o->out, "output .png (16-bit), .pgm (16-bit) or .npy (float32)");
                    app.add_option("--pov", o->pov, "also write a POV-Ray scene (.pov, with its PNG beside it)");
                    app.add_flag("--stats", o->stats, "print a JSON object: seconds, min, max, mean, std");
                    return [o] {
                      if (o->out.empty() && o->pov.empty() && !o->stats) invalid("give --out FILE, --pov FILE and/or --stats");
                      return run(*o);
                    };
                  },
                  10});

}  // namespace
}  // namespace ft::cli
