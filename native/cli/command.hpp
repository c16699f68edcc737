// SPDX-License-Identifier: GPL-3.0-or-later
// Subcommands register themselves: each cmd_*.cpp defines one Command and a
// static Registration, so adding a subcommand is adding a file.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace ft::cli {

// setup() adds the subcommand's options to `app` and returns the action to
// run when it is chosen; the action returns the process exit code.
struct Command {
  std::string name;
  std::string description;
  std::function<std::function<int()>(CLI::App& app)> setup;
  int order = 100;  // position in --help
};

std::vector<Command>& registry();

struct Registration {
  explicit Registration(Command c) { registry().push_back(std::move(c)); }
};

}  // namespace ft::cli
