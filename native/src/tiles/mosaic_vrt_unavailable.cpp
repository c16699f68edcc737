// SPDX-License-Identifier: GPL-3.0-or-later
// Stands in for mosaic_vrt.cpp in a build without GDAL (FT_WITH_GDAL=OFF:
// the Windows build): TileSet::finish leaves the mosaic out (the set's
// tiles are complete without it); a preview of a set refuses, naming GDAL.
#include "core/build_features.hpp"
#include "tiles/mosaic_vrt.hpp"

namespace ft::tiles {

void write_mosaic_vrt(const TileSpec&, const std::string& dir) {
  needs("the VRT mosaic of tile set '" + dir + "'", "GDAL");
}
void write_map_vrt(const TileSpec&, const std::string& dir, int) {
  needs("the map mosaics of tile set '" + dir + "'", "GDAL");
}
Heightfield read_mosaic_preview(const std::string& dir, int32_t) {
  needs("a preview of tile set '" + dir + "' (its VRT mosaic)", "GDAL");
}

}  // namespace ft::tiles
