// SPDX-License-Identifier: GPL-3.0-or-later
// Lines drawn as ribbons, cut where a ribbon would reach into water: a river
// drawn over a lake stood its ribbon's height over the lake's surface (a dark
// patch where a wide river joins two lakes), so the drawn river ends where its
// ribbon reaches the shore and starts again where it has left the water.
#pragma once

#include "core/polyline_set.hpp"

namespace ft::contour {

// The parts of each line of `lines` whose ribbon stays out of the polygons of
// `rings`, each part a line of its own (in order, a line's parts one after
// another). A ribbon: at each point of an edge, a cross-section square to the
// edge (in 3D: it leans along a sloping edge) reaching the larger of the
// edge's two radii to each side and `flat` x that up and down (an ellipse);
// so it ends flat at a cut. `rings`: closed rings in the lines' (x, y) (the last vertex
// may repeat the first), read even-odd: shorelines with their islands (z is
// ignored). A cut's point is interpolated (z, radius) along its edge; parts
// with fewer than two distinct points are dropped.
PolylineSet clip_ribbons(const PolylineSet& lines, const PolylineSet& rings, double flat);

}  // namespace ft::contour
