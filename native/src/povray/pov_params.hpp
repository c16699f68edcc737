// SPDX-License-Identifier: GPL-3.0-or-later
// The tables of ft_pov_scene_params and ft_pov_sweep_params
// (fracterra/params.h), and their settings carried into the exporter's own
// types after the tables' range checks (for the C ABI and the CLI alike).
#pragma once

#include <span>

#include "core/param_binding.hpp"
#include "core/param_table.hpp"
#include "fracterra/povray.h"
#include "povray/scene.hpp"
#include "povray/sphere_sweep_export.hpp"

namespace ft::pov {

const ParamTable& scene_param_table();
const ParamTable& sweep_param_table();

// Checks `c`'s settings against the table and copies them into `s`: world
// sizes, vertical scale, sea, camera (framed or given), sun and scene light.
// The terrain, its colours, the line sets and the image path are data the
// caller hands over in its own types.
void apply_scene_settings(const ft_pov_scene_params& c, SceneParams& s);
// Checks `c` against the table and returns it as SweepOptions.
SweepOptions sweep_options(const ft_pov_sweep_params& c);
// Which row goes where (unbound_rows() of them is empty: a test holds it).
std::span<const ParamBinding<SceneParams>> scene_bindings();
std::span<const ParamBinding<SweepOptions>> sweep_bindings();

}  // namespace ft::pov
