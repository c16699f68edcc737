// SPDX-License-Identifier: GPL-3.0-or-later
// Level sets of a heightfield by marching squares.
//
// Coordinates: x = column, y = row (sample units, x in [0, width - 1], y in
// [0, height - 1]), z = the level. Every vertex lies on a grid edge, placed by
// linear interpolation between the edge's two samples, so it is exactly on
// the level of the piecewise-linear reading of the samples.
//
// Chains are ordered with "land" (samples >= level) on the left, in the
// right-handed (x, y) frame. Hence closed loops around land (islands) run
// counter-clockwise and have positive signed area; loops around water
// (lakes) run clockwise, negative area. A closed loop repeats its first
// vertex at the end; an open chain starts and ends on the border.
//
// Saddle cells (diagonal corners on the same side) are resolved by the mean
// of the four corners: when it is >= level the land corners are joined through
// the centre, otherwise the water corners are. Every cell decides alone and
// each edge crossing belongs to exactly two cells, so chains never cross or
// break.
#pragma once

#include <vector>

#include "core/heightfield.hpp"
#include "core/polyline_set.hpp"

namespace ft::contour {

// Throws FT_ERR_INVALID_ARGUMENT for NaN/infinite samples or level, or a
// heightfield smaller than 2 x 2. A level outside the data range (or a
// constant field) gives an empty set.
PolylineSet marching_squares(const Heightfield& hf, double level);
// The level sets at several levels, one after another in the order given
// (z tells them apart), e.g. the contour lines of a map.
PolylineSet marching_squares(const Heightfield& hf, const std::vector<double>& levels);

enum class ChainKind { kOpen, kIsland, kLake };
// Classifies polyline `i` of a marching_squares result.
ChainKind chain_kind(const PolylineSet& set, int64_t i);
// Signed area (shoelace) of polyline i taken as closed; > 0 counter-clockwise.
double signed_area(const PolylineSet& set, int64_t i);

}  // namespace ft::contour
