// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra relief: a shaded-relief preview PNG of a heightfield.
#include <memory>

#include "cli/command.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "preview/relief.hpp"

namespace ft::cli::cmd_relief {
namespace {

struct ReliefCli {
  std::string in, out;
  preview::ReliefOptions o;
};

Registration reg({"relief", "Draw a shaded-relief preview PNG of a heightfield",
                  [](CLI::App& app) -> std::function<int()> {
                    auto c = std::make_shared<ReliefCli>();
                    app.add_option("--in", c->in, io::kHeightfieldReadHelp)->required()->check(existing_file);
                    app.add_option("--out", c->out, "output RGB .png")->required();
                    app.add_option("--sea-fraction", c->o.sea_fraction, "fraction of the height range under water, 0..1")
                        ->capture_default_str();
                    app.add_option("--exaggeration", c->o.exaggeration,
                                   "vertical exaggeration (0 = automatic)")->capture_default_str();
                    app.add_option("--sun-azimuth", c->o.sun_azimuth, "degrees clockwise from image up")
                        ->capture_default_str();
                    app.add_option("--sun-elevation", c->o.sun_elevation, "degrees above the horizon, 0..90")
                        ->capture_default_str();
                    return [c] {
                      const Heightfield hf = io::read_heightfield(c->in);
                      const auto rgb = preview::shaded_relief(hf, c->o);
                      io::write_png_rgb(c->out, hf.width(), hf.height(), rgb.data());
                      return 0;
                    };
                  },
                  90});

}  // namespace
}  // namespace ft::cli::cmd_relief
