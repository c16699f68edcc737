// SPDX-License-Identifier: GPL-3.0-or-later
// Vector data (GeoJSON, GeoPackage) through GDAL's OGR: layers of features,
// each a LineString or a Polygon (outer ring, then holes) with numeric
// properties. Coordinates come in world units (x = column x spacing,
// y = row x spacing) and are written in the terrain's map coordinates and
// CRS when it has a georeference (sample centres at pixel centres), else
// as they are. The file is made in /vsimem/ and written atomically.
#pragma once

#include <string>
#include <vector>

#include "core/heightfield.hpp"
#include "core/polyline_set.hpp"

namespace ft::io {

struct VectorLayer {
  std::string name;
  bool polygons = false;                  // Polygon features, else LineString
  std::vector<std::string> fields;        // property names
  std::vector<bool> integer;              // per field: written as an integer
  std::vector<std::string> string_fields; // extra text properties (e.g. how a river ends)
  std::vector<std::vector<std::vector<Vec3>>> geometry;  // per feature: its rings (a line: one)
  std::vector<std::vector<double>> values;               // per feature: one per field
  std::vector<std::vector<std::string>> strings;         // per feature: one per string field
};

// `spacing` turns world units into columns and rows for the georeference.
// `.geojson` / `.json` (GeoJSON, one layer: the first) or `.gpkg` (every layer).
void write_vector_layers(const std::vector<VectorLayer>& layers, const GeoReference& geo, double spacing,
                         const std::string& path);

}  // namespace ft::io
