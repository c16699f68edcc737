// SPDX-License-Identifier: GPL-3.0-or-later
// Splat rules as JSON, read and written through the table of ft_splat_params
// (splat_params.cpp), so the file's fields are the table's:
//   {"layers": [{"name": "rock", "slope_min": 33, "slope_blend": 12,
//                "weight": 3, "color": [0.46, 0.43, 0.40]}, ...]}
// A field left out keeps the table's default. Unknown fields, a layer
// without a name, two layers of one name, a value of the wrong type or out
// of its range are refused with a message naming the layer and the field.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "fracterra/splat.h"

namespace ft::splat {

struct SplatRules {
  std::deque<std::string> names;      // what layers[k].name points to
  std::vector<ft_splat_params> layers;
};

SplatRules parse_rules(const std::string& json_text, const std::string& source);
SplatRules read_rules(const std::string& path);
std::string rules_to_json(const std::vector<ft_splat_params>& layers);

}  // namespace ft::splat
