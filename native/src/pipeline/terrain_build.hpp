// The terrain pipeline: generate -> landform -> erode -> maps -> rivers, one
// call with one progress callback (fracterra/pipeline.h). The CLI and the C
// ABI (so the Blender add-on) both come through here, so the stages are put
// together once, with one rule for a terrain that tiles (a torus).
#pragma once

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
Heightfield build_terrain(const ft_build_params& p, erosion::ErosionMaps* maps,
                          hydrology::RiverNetwork* rivers = nullptr);

// The erosion settings of a build for `terrain` (the generated terrain): the
// given settings (or the defaults), the preset fitted to the terrain over
// them, and the torus rule of the terrain's method; threads and progress unset.
erosion::ErosionConfig build_erosion_config(const ft_build_params& p, const Heightfield& terrain);

// The rivers stage's settings for terrain `t` (upgraded and range-checked):
// p.rivers (or the defaults) with the terrain's torus rule (periodic when it
// tiles), the terrain's own sea when it has one, the build's threads; no progress.
hydrology::HydrologyConfig build_rivers_config(const ft_build_params& p, const ft_terrain_params& t);

}  // namespace ft::pipeline
