// SPDX-License-Identifier: GPL-3.0-or-later
// The GDAL VRT mosaic of a finished tile set, so that gdalinfo, QGIS and
// every GDAL reader open the whole as one raster: built by GDALBuildVRT from
// the tiles' georeferencing (world files for PNG, the GeoTIFFs' own), with
// the 16-bit tiles' common scale as the band's offset and scale (real height
// = offset + scale * value), and overviews (factors 2, 4, ... down to about
// 256 samples a side, averaged) in an external mosaic.vrt.ovr. Both files are
// made under temporary names and renamed into place.
#pragma once

#include <string>

#include "core/heightfield.hpp"
#include "tiles/tile_writer.hpp"

namespace ft::tiles {

inline constexpr const char* kMosaicName = "mosaic.vrt";

void write_mosaic_vrt(const TileSpec& spec, const std::string& dir);
// "maps/deposited.vrt": the mosaic of map k (kMapNames order) of a set with
// maps, float32 in the map's units, without overviews.
inline std::string map_vrt_name(int k) { return std::string("maps/") + kMapNames[size_t(k)] + ".vrt"; }
void write_map_vrt(const TileSpec& spec, const std::string& dir, int k);

// A coarse preview of a finished tile set's whole terrain in real heights,
// at most max_side samples a side (aspect kept), read through the mosaic and
// its overviews (cheap for any size of set): for framing a camera or a sea
// level, not for measuring. Its world size is the whole's.
Heightfield read_mosaic_preview(const std::string& dir, int32_t max_side);

}  // namespace ft::tiles
