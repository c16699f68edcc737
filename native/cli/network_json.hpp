// SPDX-License-Identifier: GPL-3.0-or-later
// The river network's measures as JSON, and the sea named by --sea-level or
// --sea-fraction: shared by `rivers`, `analyze` and `terrain --rivers`.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "fracterra/hydrology.h"
#include "hydrology/network_measures.hpp"

namespace ft::cli {

nlohmann::json network_json(const hydrology::NetworkMeasures& m);
// --sea-level H or --sea-fraction F given without --sea name the sea; both is an error.
void sea_from_flags(const CLI::App& app, ft_hydrology_params& p);

}  // namespace ft::cli
