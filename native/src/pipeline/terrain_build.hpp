// SPDX-License-Identifier: GPL-3.0-or-later
// The terrain pipeline: generate -> landform -> erode -> maps -> rivers, one
// call with one progress callback (fracterra/pipeline.h). The CLI and the C
// ABI (so the Blender add-on) both come through here, so the stages are put
// together once, with one rule for a terrain that tiles (a torus);
// `fracterra erode --in` runs the erode stage alone through the same calls.
#pragma once

#include <string>

#include "core/heightfield.hpp"
#include "erosion/erosion.hpp"
#include "fracterra/pipeline.h"
#include "hydrology/hydrology.hpp"

namespace ft::pipeline {

// Validates everything before any work (the terrain's and the erosion's
// params, the preset), then runs the stages. `maps` may be null; when not,
// it receives the result's maps (of the eroded terrain, or of the generated
// one without erosion). `rivers` may be null; when not, it receives the
// rivers, lakes and sea of the result (p.rivers' settings, or the defaults,
// under build_rivers_config's rules). Throws ft::Error naming what is wrong.
// `world` may be null; when not, it receives the built terrain's world (ft_terrain_world:
// whether it tiles, its own sea), what erode_made and rivers_made continue from.
Heightfield build_terrain(const ft_build_params& p, erosion::ErosionMaps* maps,
                          hydrology::RiverNetwork* rivers = nullptr, ft_terrain_world* world = nullptr);

// The erode stage of build_terrain on a terrain already made (ft_terrain_erode): p.erosion and
// p.erosion_preset fitted to `hf`, p's threads and progress; `world` (null: the erosion's own
// periodic and sea fields) as build_terrain_world reported it. A world size of 0 is taken as 10.
Heightfield erode_made(const ft_build_params& p, const Heightfield& hf, const ft_terrain_world* world,
                       erosion::ErosionMaps* maps);

// The rivers stage of build_terrain on a terrain already made (ft_terrain_rivers).
hydrology::RiverNetwork rivers_made(const ft_build_params& p, const Heightfield& hf, const ft_terrain_world* world);

// The window [x0, x0 + w) x [y0, y0 + h) of build_terrain(p, maps): the same
// bits as those samples of the whole, heights and maps (`maps` may be null).
// The world size recorded is the window's share of the terrain's. Throws for
// a window outside the terrain's extent, and for what has no windows (the
// terrain's own rules: spectral synthesis, a sea given as a fraction).
Heightfield build_terrain_window(const ft_build_params& p, int64_t x0, int64_t y0, int32_t w, int32_t h,
                                 erosion::ErosionMaps* maps);

// The erosion settings for `terrain`: `given` (null: the table's defaults)
// with the preset named `preset` (an id, label or old id; "": none) fitted to
// the terrain over it. The preset sets the pass counts and every value it
// changes from the defaults; the rest stays as given. What build_terrain
// erodes with, before its torus rule, threads and progress.
ft_erosion_params erosion_settings(const ft_erosion_params* given, const std::string& preset,
                                   const Heightfield& terrain);

// The erode stage on a terrain already made (build_terrain's, or a file's in
// `fracterra erode --in`): `e` (checked against the table) on `hf`. A
// periodic `e` erodes `hf` as a torus; `overlap` is the number of last rows
// and columns that repeat the first (a dyadic periodic grid's 1, see
// TerrainMethod::period_overlap): they are left out of the torus and copied
// back after. `maps` and `budget` may be null.
Heightfield erode_terrain(const Heightfield& hf, const ft_erosion_params& e, int overlap, erosion::ErosionMaps* maps,
                          erosion::MassBudget* budget = nullptr);

// The rivers stage's settings for terrain `t` (upgraded and range-checked):
// p.rivers (or the defaults) with the terrain's torus rule (periodic when it
// tiles), the terrain's own sea when it has one, the build's threads; no progress.
hydrology::HydrologyConfig build_rivers_config(const ft_build_params& p, const ft_terrain_params& t);

}  // namespace ft::pipeline
