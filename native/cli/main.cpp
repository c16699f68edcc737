// SPDX-License-Identifier: GPL-3.0-or-later
// The fracterra command-line tool: every generator, measure and exporter of
// the library without Blender.
#include <algorithm>
#include <cstdio>

#include "cli/command.hpp"
#include "core/build_features.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"

namespace ft::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace ft::cli

int main(int argc, char** argv) {
  using namespace ft::cli;
  CLI::App app{"fracterra: fractal terrains and polylines for Blender and POV-Ray"};
  app.require_subcommand(1);
  // Wide enough that "--octave-rotation FLOAT=0.5" keeps two spaces before its text.
  app.get_formatter()->column_width(40);
  // The version names what this build has: the Windows build goes without
  // GDAL, OpenEXR and OpenSubdiv (docs/windows.md).
  app.set_version_flag("--version", std::string("fracterra " FT_VERSION_STRING "\nheightfield formats: ") +
                                        ft::heightfield_formats() + "\noptional libraries: " +
                                        (*ft::build_features() ? ft::build_features() : "none"));
  auto& commands = registry();
  std::stable_sort(commands.begin(), commands.end(),
                   [](const Command& a, const Command& b) { return a.order < b.order; });
  std::function<int()> action;
  for (auto& c : commands) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    auto run = c.setup(*sub);
    sub->callback([&action, run] { action = run; });
  }
  try {
    // UTF-8 arguments (on Windows taken from the wide command line, so that
    // "Dossier été" reaches the library intact); CLI11 takes them reversed.
    std::vector<std::string> args = ft::platform::utf8_arguments(argc, argv);
    args.erase(args.begin());
    std::reverse(args.begin(), args.end());
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return action ? action() : 0;
  } catch (const ft::Error& e) {
    std::fprintf(stderr, "fracterra: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "fracterra: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fracterra: internal error: %s\n", e.what());
    return 3;
  }
}
