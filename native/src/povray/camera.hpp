// A perspective camera framed on a box of content, and the projection
// POV-Ray's camera makes of it (so tests can say where a point must land).
#pragma once

#include "core/polyline_set.hpp"

namespace ft::pov {

struct CameraOptions {
  double azimuth_deg = 200;    // compass direction from the content to the camera: 0 = +y (north), 90 = +x
  double elevation_deg = 30;   // above the horizon, 1..90
  double fov_deg = 45;         // horizontal field of view (POV-Ray `angle`), 5..150
  double aspect = 4.0 / 3.0;   // image width / height the framing is made for, 0.1..10
  double margin = 0.04;        // free border, fraction of the half-frame, 0..0.5
  double distance_scale = 1;   // > 1 moves the camera away from the framed distance, 0.1..100
};

struct Camera {
  Vec3 location{}, look_at{};    // POV axes
  Vec3 right{}, up{}, direction{};  // unit vectors (POV axes, left-handed)
  double fov_deg = 45, aspect = 4.0 / 3.0;
  // Image position of a POV point in 0..1 (u right, v down from the top);
  // false when it is behind the camera.
  bool project(const Vec3& p, double& u, double& v) const;
};

void validate_camera_options(const CameraOptions& o);
// The camera that looks at the centre of the POV box [lo, hi] from the
// given direction, just far enough for all 8 corners to fit the frame.
Camera frame_box(const Vec3& lo, const Vec3& hi, const CameraOptions& o);

}  // namespace ft::pov
