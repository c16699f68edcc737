// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON report of a polyline set that `fracterra polyline --stats` prints
// and `fracterra analyze FILE.csv|.json` returns for polyline inputs.
#pragma once

#include <nlohmann/json.hpp>

#include "core/polyline_set.hpp"

namespace ft::analysis {

// {"lines", "vertices", "length", "eta", "chi", "gamma", "mass_dimension",
//  "box_counting": {"dimension", "std_error", "min_size", "max_size",
//  "sizes": [...], "counts": [...]} or {"error": "..."}}. NaN values are null.
nlohmann::json polyline_report(const PolylineSet& set);

}  // namespace ft::analysis
