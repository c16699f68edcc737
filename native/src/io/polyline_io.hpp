// SPDX-License-Identifier: GPL-3.0-or-later
// Polyline sets as text:
//   .csv   one vertex per line "x,y,z[,radius]" (or "x,y"), a blank line
//          between polylines, '#' comment lines allowed; written with 17
//          significant digits so a round trip is exact. A header line
//          "# x,y,z,radius,a,b,..." names further columns (a river file's
//          discharge, width, ...): each row then has them all, and reading
//          keeps x, y, z and radius.
//   .json  {"polylines": [{"points": [[x, y, z], ...], "radii": [...]}, ...]}
#pragma once

#include <string>

#include "core/polyline_set.hpp"

namespace ft::io {

void write_polylines(const PolylineSet& set, const std::string& path);
PolylineSet read_polylines(const std::string& path);
PolylineSet decode_polylines_csv(const std::string& text, const std::string& name = "<memory>");
PolylineSet decode_polylines_json(const std::string& text, const std::string& name = "<memory>");
std::string encode_polylines_csv(const PolylineSet& set);
std::string encode_polylines_json(const PolylineSet& set);

}  // namespace ft::io
