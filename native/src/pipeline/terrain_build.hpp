// The terrain pipeline: generate -> landform -> erode -> maps, one call with
// one progress callback (fracterra/pipeline.h). The CLI and the C ABI (so the
// Blender add-on) both come through here, so the stages are put together
// once. A later stage (rivers) is one more step in build_terrain.
#pragma once

#include "core/heightfield.hpp"
#include "erosion/erosion.hpp"
#include "fracterra/pipeline.h"

namespace ft::pipeline {

// Validates everything before any work (the terrain's and the erosion's
// params, the preset), then runs the stages. `maps` may be null; when not,
// it receives the result's maps (of the eroded terrain, or of the generated
// one without erosion). Throws ft::Error naming what is wrong.
Heightfield build_terrain(const ft_build_params& p, erosion::ErosionMaps* maps);

// The erosion settings of a build for `terrain` (the generated terrain): the
// given settings (or the defaults), the preset fitted to the terrain over
// them, and the torus rule of the terrain's method; threads and progress unset.
erosion::ErosionConfig build_erosion_config(const ft_build_params& p, const Heightfield& terrain);

}  // namespace ft::pipeline
