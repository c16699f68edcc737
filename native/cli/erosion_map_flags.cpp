#include "cli/erosion_map_flags.hpp"

#include "io/heightfield_io.hpp"

namespace ft::cli {

void ErosionMapFlags::add_to(CLI::App& app) {
  const std::string raster = std::string(io::kHeightfieldReadHelp) +
                             "; 8/16-bit images read as 0..1, other rasters must hold 0..1; spans the terrain "
                             "corner to corner, resampled bilinearly, image row 0 (the top) at terrain row 0";
  app.add_option("--erosion-mask", erosion_mask,
                 "where erosion acts: white (1) erodes fully, black (0) not at all (sediment may still settle "
                 "there); " + raster)
      ->check(CLI::ExistingFile);
  app.add_option("--rain-map", rain_map, "where rain falls: white (1) full rainfall, black (0) none; " + raster)
      ->check(CLI::ExistingFile);
}

void ErosionMapFlags::apply(erosion::ErosionConfig& c) {
  if (!erosion_mask.empty()) {
    mask_grid = io::read_heightfield(erosion_mask);
    c.erosion_mask = {mask_grid.data(), mask_grid.width(), mask_grid.height()};
  }
  if (!rain_map.empty()) {
    rain_grid = io::read_heightfield(rain_map);
    c.rain_map = {rain_grid.data(), rain_grid.width(), rain_grid.height()};
  }
}

void ErosionMapFlags::apply(ft_erosion_params& p) {
  erosion::ErosionConfig c;
  apply(c);
  if (!erosion_mask.empty())
    p.erosion_mask = c.erosion_mask.values, p.erosion_mask_width = c.erosion_mask.width,
    p.erosion_mask_height = c.erosion_mask.height;
  if (!rain_map.empty())
    p.rain_map = c.rain_map.values, p.rain_map_width = c.rain_map.width, p.rain_map_height = c.rain_map.height;
}

}  // namespace ft::cli
