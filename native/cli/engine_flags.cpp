// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/engine_flags.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "engines/engine_export.hpp"

namespace ft::cli {

void EngineFlags::add_to(CLI::App& app) {
  app.add_option("--engine", engine,
                 "write --out for a game engine: unity (RAW16 .raw, 2^n + 1 square), unreal (16-bit .png, 505, "
                 "1009, 2017, 4033 or 8129 square, Z scale in the sidecar), godot (Terrain3D: .exr heights and "
                 "NAME_control.exr at a multiple of --region-size); the numbers for the importer go to OUT.json "
                 "(docs/engines.md)")
      ->check(CLI::IsMember({"unity", "unreal", "godot"}));
  app.add_option("--engine-size", side,
                 "samples per side for --engine (one the engine takes) [default: the nearest to the terrain's]");
  app.add_option("--region-size", region_size, "--engine godot: Terrain3D's region size, 64..2048, a power of two")
      ->capture_default_str();
}

void EngineFlags::check(const std::string& out) const {
  if (!given()) return;
  if (out.empty()) invalid("--engine writes --out: give --out FILE");
  engines::check_engine_output({engines::parse_engine(engine), region_size, side}, out);
}

int32_t EngineFlags::generation_side(int32_t requested) const {
  if (!given()) return 0;
  engines::EngineOptions o{engines::parse_engine(engine), region_size, side};
  return side ? side : engines::engine_side(o.engine, requested, region_size);
}

void EngineFlags::write(const Heightfield& hf, const std::string& out, const splat::SplatInputs& maps) const {
  const engines::EngineOptions o{engines::parse_engine(engine), region_size, side};
  engines::write_for_engine(hf, out, o, maps);
}

}  // namespace ft::cli
