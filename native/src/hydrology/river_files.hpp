// SPDX-License-Identifier: GPL-3.0-or-later
// River networks as files:
//   .csv      the polyline format (io/polyline_io) with the header
//             "# x,y,z,radius,discharge,width,depth,area,segment,order": one
//             vertex per row, a blank line between segments;
//   .json     the polyline format's {"polylines": [...]} with, per polyline,
//             "discharge", "width", "depth", "area" (per vertex), "order",
//             "stream", "downstream", "end", "lake", "from_lake", "length",
//             and "lakes": [{"level", "area", "volume", "outlet", "rings"}];
//   .geojson  rivers as LineStrings with their properties (OGR);
//   .gpkg     a "rivers" and a "lakes" layer (OGR).
// Lakes alone (--lakes): .geojson or .gpkg Polygons, or .json.
#pragma once

#include <string>
#include <vector>

#include "core/heightfield.hpp"
#include "core/polyline_set.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

// `geo`: the terrain's georeference (GeoJSON and GeoPackage are written in
// its CRS and map coordinates when it has one).
void write_rivers(const RiverNetwork& net, const GeoReference& geo, const std::string& path);
void write_lakes(const RiverNetwork& net, const GeoReference& geo, const std::string& path);

// What a scene needs from a river .json: the rivers (radius = half width)
// and each lake's shoreline rings at its level.
struct WaterScene {
  PolylineSet rivers;
  struct LakeShape {
    double level = 0;
    std::vector<std::vector<Vec3>> rings;  // the outer shoreline first
  };
  std::vector<LakeShape> lakes;
};
WaterScene read_water_json(const std::string& path);

}  // namespace ft::hydrology
