// SPDX-License-Identifier: GPL-3.0-or-later
// --engine unity|unreal|godot, --engine-size N and --region-size N, shared
// by `terrain` and `erode`: the output written the way the engine's
// importer takes it (engines/engine_export.hpp), with its sidecar.
#pragma once

#include <string>

#include "cli/cli_util.hpp"
#include "core/heightfield.hpp"
#include "splat/splat_map.hpp"

namespace ft::cli {

struct EngineFlags {
  std::string engine;  // "" when not given
  int32_t side = 0, region_size = 256;

  void add_to(CLI::App& app);
  bool given() const { return !engine.empty(); }
  // Refuses bad engine settings for `out` before the work.
  void check(const std::string& out) const;
  // The side to generate at for a method that takes a size (0: keep).
  int32_t generation_side(int32_t requested) const;
  // Writes `hf` to `out` for the engine; the maps feed Godot's control map.
  void write(const Heightfield& hf, const std::string& out, const splat::SplatInputs& maps = {}) const;
};

}  // namespace ft::cli
