// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/splat_sources.hpp"

#include "erosion/presets.hpp"

namespace ft::cli {

SplatSources read_splat_sources(const std::string& rules_path, const std::string& maps_dir) {
  SplatSources s;
  if (!rules_path.empty()) s.rules = splat::read_rules(rules_path);
  else s.rules.layers = splat::default_layers();
  if (!maps_dir.empty()) {
    s.deposited = erosion::read_erosion_map(maps_dir, "deposited");
    s.drainage_area = erosion::read_erosion_map(maps_dir, "drainage_area");
    s.has_maps = true;
  }
  return s;
}

}  // namespace ft::cli
