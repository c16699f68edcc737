// The terrain pipeline: generate -> landform -> erode -> maps, one call with
// one progress callback (fracterra/pipeline.h). The CLI and the C ABI (so the
// Blender add-on) both come through here, so the stages are put together
// once; `fracterra erode --in` runs the erode stage alone through the same
// calls. A later stage (rivers) is one more step in build_terrain.
#pragma once

#include <string>

#include "core/heightfield.hpp"
#include "erosion/erosion.hpp"
#include "fracterra/pipeline.h"

namespace ft::pipeline {

// Validates everything before any work (the terrain's and the erosion's
// params, the preset), then runs the stages. `maps` may be null; when not,
// it receives the result's maps (of the eroded terrain, or of the generated
// one without erosion). Throws ft::Error naming what is wrong.
Heightfield build_terrain(const ft_build_params& p, erosion::ErosionMaps* maps);

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

}  // namespace ft::pipeline
