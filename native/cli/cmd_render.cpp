// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra render: run POV-Ray on a scene and write a PNG.
#include <cstdio>
#include <memory>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/path_checks.hpp"
#include "povray/render.hpp"

namespace ft::cli::cmd_render {
namespace {

struct RenderCliOptions {
  std::string scene, out;
  pov::RenderOptions r;
};

// Shared with `fracterra scene --render`: the size and quality options.
Registration reg({"render", "Render a POV-Ray scene to a PNG with povray",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<RenderCliOptions>();
                    app.add_option("scene", o->scene, "the .pov scene")->required()->check(existing_file);
                    app.add_option("--out", o->out, "output PNG (written under a temporary name, renamed when done)")
                        ->required();
                    app.add_option("--width", o->r.width, "image width in pixels")->check(CLI::Range(1, 16384))
                        ->capture_default_str();
                    app.add_option("--height", o->r.height, "image height in pixels")->check(CLI::Range(1, 16384))
                        ->capture_default_str();
                    app.add_option("--antialias", o->r.antialias,
                                   "anti-aliasing threshold (povray +A), 0 = off; 0..3")
                        ->check(CLI::Range(0.0, 3.0))->capture_default_str();
                    app.add_option("--include", o->r.include_paths,
                                   "extra folder for #include files (povray +L), e.g. povray_macros; repeatable")
                        ->check(existing_directory);
                    app.add_option("--povray", o->r.povray, "povray program (default: $FT_POVRAY or povray)");
                    app.add_flag("--verbose", o->r.verbose, "print all of POV-Ray's messages");
                    return [o] {
                      Stopwatch clock;
                      const auto res = pov::render_scene(o->scene, o->out, o->r);
                      if (o->r.verbose || res.warnings > 0) std::fputs(res.messages.c_str(), stderr);
                      std::printf("rendered %s (%dx%d) in %.2f s\n", o->out.c_str(), o->r.width, o->r.height,
                                  clock.seconds());
                      return 0;
                    };
                  },
                  90});

}  // namespace
}  // namespace ft::cli::cmd_render
