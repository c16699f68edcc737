// SPDX-License-Identifier: GPL-3.0-or-later
// Drainage area by multiple flow directions, for the maps artists texture by.
//
// Single-flow routing (D8, flow_graph.hpp) is what the eroders and the
// drainage statistics need: one receiver per cell, a stack, channels with a
// length. As a picture it is wrong: every cell sends all its water to one of
// eight neighbours, so on gentle slopes and valley floors the area gathers
// in straight grid-aligned lines that a material shows as streaks. Here each
// cell divides its water among all its lower neighbours in proportion to
// contour length times slope (Quinn, Beven, Chevallier & Planchon 1991,
// "The prediction of hillslope flow paths for distributed hydrological
// modelling using digital terrain models"): water spreads on hillslopes and
// fans, and still gathers in valleys, whose sides all slope toward them.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/flat_resolution.hpp"

namespace ft::erosion {

// Drainage area in world units^2 (each cell spacing^2, including its own) on
// `z`, which must drain: every cell that is not a base level (a bounded
// grid's edge, a periodic grid's `sink`) has a strictly lower neighbour, as
// after fill_depressions. Base levels keep what reaches them, so the base
// levels' areas sum to the grid's area. Cells are visited once each in
// topological order (a cell after all its higher neighbours), each summing
// what its higher neighbours give in a fixed order: the result is the same
// on any thread count. `progress` hears the share done, every 64th of the
// cells, from the calling thread; a cancel stops it (FT_ERR_CANCELLED).
// With `flats` (resolve_flats on `z`), `z` may hold flats: their cells give
// to the neighbours of the same height whose key is lower, by the key's fall;
// the other cells' shares are the heights' as without it. `inflow` (may be
// null) adds water from outside the grid: each (cell, area) adds the area
// to that cell's own before it is passed on, in the list's order.
using Inflow = std::vector<std::pair<int32_t, double>>;
void multiple_flow_area(const D8Grid& g, const float* z, int32_t sink, std::vector<double>& area,
                        const Progress& progress = Progress(), const FlatGrading* flats = nullptr,
                        const Inflow* inflow = nullptr);

// What each cell gives each neighbour k (world units^2) by the rules of
// multiple_flow_area, given its `area` on the same z, sink and flats: a
// giver's area split by contour length times fall; 0 from base levels.
// One serial pass, for small grids (the model's).
std::vector<std::array<double, 8>> multiple_flow_given(const D8Grid& g, const float* z, int32_t sink,
                                                       const FlatGrading* flats, const std::vector<double>& area);

}  // namespace ft::erosion
