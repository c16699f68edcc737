// SPDX-License-Identifier: GPL-3.0-or-later
// What the splat rules read, as `fracterra splat` and `fracterra scene` take
// it: a rules file (--rules; none: the built-in set) and the folder of
// `fracterra erode --maps` (--maps; none: the deposit and flow conditions
// see no erosion).
#pragma once

#include <string>

#include "core/heightfield.hpp"
#include "splat/rules_json.hpp"
#include "splat/splat_map.hpp"

namespace ft::cli {

struct SplatSources {
  splat::SplatRules rules;
  Heightfield deposited, drainage_area;
  bool has_maps = false;

  // The rules' inputs over `terrain` (which must outlive them).
  splat::SplatInputs inputs(const Heightfield& terrain) const {
    return {&terrain, has_maps ? &deposited : nullptr, has_maps ? &drainage_area : nullptr};
  }
  int32_t layer_count() const { return int32_t(rules.layers.size()); }
};

SplatSources read_splat_sources(const std::string& rules_path, const std::string& maps_dir);

}  // namespace ft::cli
