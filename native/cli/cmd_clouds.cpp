// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra clouds: Feder's clouds (seed 001) from a heightfield.
#include <memory>

#include "analysis/analysis_params.hpp"
#include "analysis/clouds.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"

namespace ft::cli::cmd_clouds {
namespace {

struct CloudsCli {
  std::string in, threshold = "q0.5", out;
  ft_clouds_params p = defaults_of<ft_clouds_params>(analysis::clouds_param_table());
};

Registration reg({"clouds",
                  "Clouds from a heightfield (Feder): black below the threshold, above it grey ~ log(elevation)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto c = std::make_shared<CloudsCli>();
                    app.add_option("--in", c->in, io::kHeightfieldReadHelp)->required();
                    // threshold and threshold_is_quantile as one flag: a height, or qF.
                    app.add_option("--threshold", c->threshold,
                                   "height below which the sky is black, or a quantile qF with F in [0, 1]")
                        ->capture_default_str();
                    add_param_flags(app, analysis::clouds_param_table(), &c->p, {"threshold", "threshold_is_quantile"},
                                    {{"bit_depth", "--bits"}});
                    app.add_option("--out", c->out, "output grey .png (an image map for POV-Ray or Blender)")
                        ->required();
                    return [c] {
                      const Heightfield hf = io::read_heightfield(c->in);
                      const analysis::LevelSpec level = analysis::parse_level(c->threshold, "--threshold");
                      c->p.threshold = level.value;
                      c->p.threshold_is_quantile = level.quantile;
                      io::write_png(c->out, analysis::clouds_image(hf, analysis::cloud_options(c->p)));
                      return 0;
                    };
                  },
                  52});

}  // namespace
}  // namespace ft::cli::cmd_clouds
