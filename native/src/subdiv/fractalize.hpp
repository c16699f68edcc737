// SPDX-License-Identifier: GPL-3.0-or-later
// Fractalize a polygon mesh: Voss midpoint displacement (or Feder's
// successive random additions) on OpenSubdiv's uniform refinement.
#pragma once

#include "core/mesh.hpp"
#include "fracterra/subdiv.h"

namespace ft::subdiv {

inline constexpr int kMaxSubdivLevels = 10;

ft_fractalize_params default_fractalize_params();

// Validates `mesh` and `p` and returns the refined, displaced mesh (quads for
// catmark/bilinear, triangles for loop). `weights` in p, when given, must hold
// mesh.vertex_count() values.
Mesh fractalize(const Mesh& mesh, const ft_fractalize_params& p);

}  // namespace ft::subdiv
