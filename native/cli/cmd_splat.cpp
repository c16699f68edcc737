// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra splat: splat (weight) maps and a colour map of a terrain by layer
// rules (the built-in ones or a rules JSON), for game engines.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/path_checks.hpp"
#include "cli/splat_sources.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "splat/rules_json.hpp"
#include "splat/splat_files.hpp"
#include "splat/splat_map.hpp"

namespace ft::cli::cmd_splat {
namespace {

struct SplatCli {
  std::string in, maps, rules, out, color;
  int depth = 8;
  double world_size = 0;
  bool print_rules = false;
};

int run(const SplatCli& o) {
  SplatSources src = read_splat_sources(o.rules, o.in.empty() ? std::string() : o.maps);
  const splat::SplatRules& rules = src.rules;
  if (o.print_rules) {
    std::printf("%s", splat::rules_to_json(rules.layers).c_str());
    if (o.in.empty()) return 0;
  }
  if (o.in.empty()) invalid("give --in TERRAIN (or --print-rules alone)");
  if (o.out.empty() && o.color.empty()) invalid("give --out SPLAT.png and/or --color COLOR.png");
  Heightfield terrain = io::read_heightfield(o.in);
  settle_world_size(terrain, o.world_size, o.in);
  const splat::SplatInputs in = src.inputs(terrain);
  const int32_t n = src.layer_count();
  nlohmann::json report = {{"layers", nlohmann::json::array()}, {"files", nlohmann::json::array()}};
  if (!o.out.empty()) {
    const auto weights = splat::splat_weights(in, rules.layers.data(), n, o.depth == 16 ? 65535 : 255);
    const auto files = splat::write_splat_pngs(o.out, weights, terrain.width(), terrain.height(), n, o.depth);
    const char* channels = "RGBA";
    for (const auto& f : files) {
      report["files"].push_back(f.path);
      for (int32_t c = 0; c < f.layers; ++c)
        report["layers"].push_back({{"name", rules.layers[size_t(f.first_layer + c)].name},
                                    {"file", f.path},
                                    {"channel", std::string(1, channels[c])}});
    }
    report["total"] = o.depth == 16 ? 65535 : 255;
  }
  if (!o.color.empty()) {
    splat::write_color_png(o.color, splat::splat_colors(in, rules.layers.data(), n), terrain.width(),
                           terrain.height());
    report["color"] = o.color;
  }
  if (!o.print_rules) std::printf("%s\n", report.dump().c_str());
  return 0;
}

Registration reg({"splat", "Write splat (weight) maps and a colour map of a terrain by layer rules",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<SplatCli>();
                    app.add_option("--in", o->in, io::kHeightfieldReadHelp)->check(existing_file);
                    app.add_option("--maps", o->maps,
                                   "the folder of fracterra erode --maps (deposited and drainage_area feed the "
                                   "sediment rule); without it those conditions see 0")
                        ->check(existing_directory);
                    app.add_option("--rules", o->rules,
                                   "layer rules JSON {\"layers\": [{\"name\": ..., fields of "
                                   "`fracterra params` ft_splat_params}]} [default: grass, rock, sediment, snow]")
                        ->check(existing_file);
                    app.add_option("--out", o->out,
                                   "RGBA .png, four layers to a file (layers 4-7 in NAME_1.png, ...); the weights "
                                   "sum to 255 (or 65535 with --depth 16) at every pixel");
                    app.add_option("--color", o->color, "also bake an RGB colour map (.png) by the same rules");
                    app.add_option("--depth", o->depth, "bits per channel of the splat maps: 8 or 16")
                        ->check(CLI::IsMember({8, 16}))
                        ->capture_default_str();
                    app.add_option("--world-size", o->world_size,
                                   "extent along x in world units when the file does not record it (slopes) "
                                   "[default: 10]");
                    app.add_flag("--print-rules", o->print_rules, "print the rules in use as JSON");
                    return [o] { return run(*o); };
                  },
                  16});

}  // namespace
}  // namespace ft::cli::cmd_splat
