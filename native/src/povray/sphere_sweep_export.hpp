// SPDX-License-Identifier: GPL-3.0-or-later
// Polylines as POV-Ray `sphere_sweep`s. One long sweep costs POV-Ray time in
// proportion to its length for every ray that meets its bounding box, so a
// polyline is cut into short sweeps of `segments_per_sweep` segments that
// share their end points, gathered in one `union`: each piece gets a tight
// bounding box and the image is the same, 50-150x faster to trace.
#pragma once

#include <cstdint>
#include <string>

#include "core/polyline_set.hpp"

namespace ft::pov {

enum class SweepSpline : int32_t { kLinear = 0, kCubic = 1 };

struct SweepOptions {
  SweepSpline spline = SweepSpline::kLinear;
  // Segments per sweep, 1..2^30; 16..64 is fast, a huge value writes one
  // sweep per polyline (the slow baseline of the benchmark).
  int64_t segments_per_sweep = 32;
  double default_radius = 0.01;  // world units, used where a vertex radius is 0; > 0
  double radius_scale = 1.0;     // multiplies every radius (taper kept); > 0
  double tolerance = 1e-3;       // cubic sweeps' intersection depth tolerance; > 0
  double z_override = 0.0;       // when use_z_override: world z of every vertex
  bool use_z_override = false;   // (coastlines drawn on the sea surface)
};

struct SweepStats {
  int64_t sweeps = 0, spheres = 0, duplicates_removed = 0;
};

void validate_sweep_options(const SweepOptions& o);

// SDL for every polyline of `set` (world axes; written in POV axes) as one
// object: `union { sphere_sweep {...} ... <modifiers> }`, or `object {...}`
// when there is a single piece, or "" when the set has no vertices.
// Repeated consecutive points (equal once written with 9 digits) are
// dropped; a polyline that shrinks to one point becomes a sphere. Linear
// sweeps have >= 2 points; cubic sweeps get one control point beyond each
// end of their piece (mirrored at the polyline's ends), so have >= 4, and
// `tolerance`. No `bounded_by`: POV-Ray 3.7 bounds each piece of a cubic
// sweep tightly itself, and removes a larger box with a warning.
std::string sweeps_sdl(const PolylineSet& set, const SweepOptions& options,
                       const std::string& modifiers = "", SweepStats* stats = nullptr);

}  // namespace ft::pov
