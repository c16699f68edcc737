// SPDX-License-Identifier: GPL-3.0-or-later
#include "tables/param_registry.hpp"

#include <string>

#include "analysis/analysis_params.hpp"
#include "core/error.hpp"
#include "erosion/erosion_params.hpp"
#include "hydrology/hydrology_params.hpp"
#include "pipeline/build_params.hpp"
#include "planet/planet_params.hpp"
#include "polyline/polyline_params.hpp"
#include "povray/pov_params.hpp"
#include "refine/dem_refine_params.hpp"
#include "splat/splat_params.hpp"
#include "subdiv/fractalize_params.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::tables {

const ParamTable& param_table(int32_t kind) {
  switch (kind) {
    case FT_PARAMS_TERRAIN: return terrain::terrain_param_table();
    case FT_PARAMS_PROFILE: return terrain::profile_param_table();
    case FT_PARAMS_POLYLINE: return polyline::polyline_param_table();
    case FT_PARAMS_FRACTALIZE: return subdiv::fractalize_param_table();
    case FT_PARAMS_POV_SCENE: return pov::scene_param_table();
    case FT_PARAMS_POV_SWEEP: return pov::sweep_param_table();
    case FT_PARAMS_HURST: return analysis::hurst_param_table();
    case FT_PARAMS_CLOUDS: return analysis::clouds_param_table();
    case FT_PARAMS_DEM_REFINE: return refine::dem_refine_param_table();
    case FT_PARAMS_EROSION: return erosion::erosion_param_table();
    case FT_PARAMS_HYDROLOGY: return hydrology::hydrology_param_table();
    case FT_PARAMS_BUILD: return pipeline::build_param_table();
    case FT_PARAMS_PLANET: return planet::planet_param_table();
    case FT_PARAMS_SPLAT: return splat::splat_param_table();
    default:
      invalid("params kind must be in 0.." + std::to_string(FT_PARAMS_KIND_COUNT - 1) + ", got " +
              std::to_string(kind));
  }
}

bool has_param_table(int32_t kind) {
  try {
    param_table(kind);
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace ft::tables
