// SPDX-License-Identifier: GPL-3.0-or-later
// --erosion-mask FILE and --rain-map FILE, shared by `erode` and
// `terrain --erode`: rasters read into the erosion settings' map fields.
#pragma once

#include <string>

#include "cli/cli_util.hpp"
#include "core/heightfield.hpp"
#include "fracterra/erosion.h"

namespace ft::cli {

struct ErosionMapFlags {
  std::string erosion_mask, rain_map;  // file names (empty: none)
  Heightfield mask_grid, rain_grid;    // what they hold, alive while the settings point at them

  void add_to(CLI::App& app);
  // Reads the files and points the settings' maps at them (checked by the
  // erosion's validate()).
  void apply(ft_erosion_params& p);
};

}  // namespace ft::cli
