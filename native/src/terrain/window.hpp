// SPDX-License-Identifier: GPL-3.0-or-later
// Windows of a terrain that never exists whole: the samples
// [x0, x0 + w) x [y0, y0 + h) of the terrain a config defines, bit-identical
// to the same samples of the whole grid, in memory O(window + halo).
//
// Diamond-square: a point of stage s reads points of stage s - 1 at most one
// coarse cell away, so a window needs, of each coarser stage, only the
// window grown by a thin halo (two cells of that stage, aligned to its
// grid). The window refiner walks the stages from the coarsest, each on a
// compact array of that halo region, with the arithmetic of
// midpoint_steps.hpp, so every point gets the bits the whole grid gives it.
// Periodic terrains are refined in unwrapped coordinates: a point's draws and
// reference values are those of its position modulo 2^levels.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "terrain/diamond_square.hpp"

namespace ft::terrain {

// A rectangle of samples in the whole terrain's coordinates.
struct Window {
  int64_t x0 = 0, y0 = 0;
  int32_t width = 0, height = 0;
};

// The window of diamond_square(config) at level of detail `lod`: sample
// (i, j) of the result is sample ((x0 + i) 2^lod, (y0 + j) 2^lod) of the
// whole. Plain midpoint never moves a point once placed, so a lod > 0 window
// is the same window of stage levels - lod and costs 4^-lod as much;
// additions move old points at every stage, so their lod > 0 windows are
// refined to full resolution over the window's footprint and subsampled.
// config.levels may reach kMaxWindowLevels (the grid is never allocated).
// Callers validate (terrain.cpp): the window lies inside the terrain.
Heightfield diamond_square_window(const DiamondSquareConfig& config, const Window& window, int lod = 0);

}  // namespace ft::terrain
