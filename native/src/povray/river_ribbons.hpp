// SPDX-License-Identifier: GPL-3.0-or-later
// Rivers as ribbons in their beds: each polyline swept by a flat ellipse,
// `width` (twice the point's radius) wide and `flat` times that high, held
// level across the river (its wide axis horizontal, at right angles to the
// flow) and square to the flow along it. That is Blender's river curve (a
// flat bevel profile, Z-up twist), so both renderers see the same water.
// A sphere_sweep squashed vertically cannot be it: squashing a round tube
// keeps its vertical thickness at r sqrt(flat^2 + s^2) on a slope s, so a
// steep river stood out of its bed by most of its width.
#pragma once

#include "core/mesh.hpp"
#include "core/polyline_set.hpp"

namespace ft::pov {

// One ring of `sides` vertices per point (consecutive repeats skipped),
// quads between rings, the two ends closed; faces counter-clockwise seen
// from outside. A line of fewer than two distinct points is left out.
// Radii <= 0 become `default_radius`.
Mesh river_ribbons(const PolylineSet& rivers, double flat, int sides, double default_radius);

}  // namespace ft::pov
