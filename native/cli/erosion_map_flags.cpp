// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/erosion_map_flags.hpp"

#include "cli/path_checks.hpp"
#include "io/heightfield_io.hpp"

namespace ft::cli {

void ErosionMapFlags::add_to(CLI::App& app) {
  const std::string raster = std::string(io::kHeightfieldReadHelp) +
                             "; 8/16-bit images read as 0..1, other rasters must hold 0..1; spans the terrain "
                             "corner to corner, resampled bilinearly, image row 0 (the top) at terrain row 0";
  app.add_option("--erosion-mask", erosion_mask,
                 "where erosion acts: white (1) erodes fully, black (0) not at all (sediment may still settle "
                 "there); " + raster)
      ->check(existing_file);
  app.add_option("--rain-map", rain_map, "where rain falls: white (1) full rainfall, black (0) none; " + raster)
      ->check(existing_file);
}

void ErosionMapFlags::apply(ft_erosion_params& p) {
  if (!erosion_mask.empty()) {
    mask_grid = io::read_heightfield(erosion_mask);
    p.erosion_mask = mask_grid.data(), p.erosion_mask_width = mask_grid.width(),
    p.erosion_mask_height = mask_grid.height();
  }
  if (!rain_map.empty()) {
    rain_grid = io::read_heightfield(rain_map);
    p.rain_map = rain_grid.data(), p.rain_map_width = rain_grid.width(), p.rain_map_height = rain_grid.height();
  }
}

}  // namespace ft::cli
