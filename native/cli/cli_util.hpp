// SPDX-License-Identifier: GPL-3.0-or-later
// Small pieces the subcommands share: name <-> enum tables for CLI11 options,
// and a stopwatch.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include "core/heightfield.hpp"

namespace ft::cli {

// A CLI11 transformer that maps names to enum values; --help lists them.
inline CLI::Transformer choice(const std::map<std::string, int>& names) {
  return CLI::Transformer(names, CLI::ignore_case);
}

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The world size a heightfield read from `path` is worked on in: `given` (--world-size, when > 0),
// else the file's own, else 10 world units, said on stderr (erosion and rivers are in world
// units: a silent default would make another terrain).
inline void settle_world_size(Heightfield& hf, double given, const std::string& path) {
  if (given > 0) return hf.set_world_size(given);
  if (hf.world_size() > 0) return;
  hf.set_world_size(10.0);
  std::fprintf(stderr, "fracterra: warning: '%s' records no world size; using the default, 10 world units "
               "(give --world-size)\n", path.c_str());
}

}  // namespace ft::cli
