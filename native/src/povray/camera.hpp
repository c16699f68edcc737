// SPDX-License-Identifier: GPL-3.0-or-later
// A perspective camera framed on a box of content, and the projection
// POV-Ray's camera makes of it (so tests can say where a point must land).
#pragma once

#include <string>
#include <vector>

#include "core/polyline_set.hpp"

namespace ft::pov {

// The ranges are ft_pov_scene_params' table's (pov_params.cpp), checked
// where settings enter the library; frame_points trusts them.
struct CameraOptions {
  double azimuth_deg = 200;    // compass direction from the content to the camera: 0 = +y (north), 90 = +x
  double elevation_deg = 22;   // above the horizon, 1..90
  double fov_deg = 50;         // horizontal field of view (POV-Ray `angle`), 5..150
  double aspect = 4.0 / 3.0;   // image width / height the framing is made for, 0.1..10
  double margin = 0.04;        // free border, fraction of the half-frame, 0..0.5
  double distance_scale = 1;   // > 1 moves the camera away from the framed distance, 0.1..100
  double center_v = 0.55;      // image row (0 top .. 1 bottom) where the middle of the framed
                               // content lands, 0.2..0.8: above 0.5 leaves more sky
};

// Another program's camera (Blender's), as POV-Ray's perspective camera
// takes it, in world axes: the ray of image point (u, v) (0..1, v down)
// runs from `location` along direction + (u - 0.5) right + (0.5 - v) up.
// Any lens, aspect and lens shift is such a triple, and so is any camera
// seen through an affine change of frame, so the vectors are kept as given.
struct CameraPose {
  Vec3 location{}, direction{}, right{}, up{};
};

struct Camera {
  Vec3 location{}, look_at{};    // POV axes
  Vec3 right{}, up{}, direction{};  // unit vectors (POV axes, left-handed)
  double fov_deg = 50, aspect = 4.0 / 3.0;
  // A given camera (camera_from_pose) is written as its own vectors (POV
  // axes, as given); the units above are theirs, fov_deg and aspect their
  // horizontal angle and ratio, look_at the image centre.
  bool given = false;
  Vec3 given_direction{}, given_right{}, given_up{};
  // Image position of a POV point in 0..1 (u right, v down from the top);
  // false when it is behind the camera.
  bool project(const Vec3& p, double& u, double& v) const;
};

// The camera of `pose` (world axes) in POV axes; throws when a vector is not
// finite or the three do not span space.
Camera camera_from_pose(const CameraPose& pose);
// The SDL `camera { ... }` statement of `c`.
std::string camera_sdl(const Camera& c);

// The camera placed towards the given azimuth and elevation from the centre
// of the points' box, tilted so the middle of their picture lands on row
// center_v, just far enough for every point to fit the frame within the margin.
Camera frame_points(const std::vector<Vec3>& points, const CameraOptions& o);
// The same for the 8 corners of the POV box [lo, hi].
Camera frame_box(const Vec3& lo, const Vec3& hi, const CameraOptions& o);

}  // namespace ft::pov
