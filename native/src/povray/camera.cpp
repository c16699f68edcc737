// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

double det(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

}  // namespace

bool Camera::project(const Vec3& p, double& u, double& v) const {
  const Vec3 d{p[0] - location[0], p[1] - location[1], p[2] - location[2]};
  if (given) {
    // d = t (direction + a right + b up): Cramer's rule for (t, t a, t b).
    const double den = det(given_direction, given_right, given_up);
    const double t = det(d, given_right, given_up) / den;
    if (t <= 0) return false;
    u = 0.5 + det(given_direction, d, given_up) / den / t;
    v = 0.5 - det(given_direction, given_right, d) / den / t;
    return true;
  }
  const double depth = dot(d, direction);
  if (depth <= 0) return false;
  // POV-Ray: the image plane spans |right| = aspect across and |up| = 1
  // down, at distance 0.5 * aspect / tan(angle / 2).
  const double t = std::tan(fov_deg * std::numbers::pi / 360);
  u = 0.5 + dot(d, right) / depth * 0.5 / t;
  v = 0.5 - dot(d, up) / depth * 0.5 * aspect / t;
  return true;
}

Camera frame_points(const std::vector<Vec3>& points, const CameraOptions& o) {
  if (points.empty()) invalid("there is nothing to frame: no points");
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const Vec3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const double size = std::max(std::sqrt(dot({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]},
                                              {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]})),
                               1e-9);
  const double az = o.azimuth_deg * std::numbers::pi / 180, el = o.elevation_deg * std::numbers::pi / 180;
  // World azimuth: 0 = +y (POV +z), 90 = +x.
  const Vec3 to_camera{std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
  const double t = std::tan(o.fov_deg * std::numbers::pi / 360);
  const Vec3 flat{-std::sin(az), 0, -std::cos(az)};
  Camera c;
  c.fov_deg = o.fov_deg;
  c.aspect = o.aspect;
  auto place = [&](double d, double tilt) {
    // The view axis is raised by `tilt` from the line to the centre.
    const double pitch = std::clamp(-el + tilt, -std::numbers::pi / 2 + 1e-6, std::numbers::pi / 2 - 1e-6);
    c.direction = {flat[0] * std::cos(pitch), std::sin(pitch), flat[2] * std::cos(pitch)};
    // Straight down, "up" in the picture is still the way the camera faces.
    const Vec3 sky = o.elevation_deg > 89.9 ? Vec3{flat[0], 0, flat[2]} : Vec3{0, 1, 0};
    c.right = unit(cross(sky, c.direction));
    c.up = cross(c.direction, c.right);
    c.location = {centre[0] + to_camera[0] * d, centre[1] + to_camera[1] * d, centre[2] + to_camera[2] * d};
    c.look_at = {c.location[0] + c.direction[0] * d, c.location[1] + c.direction[1] * d,
                 c.location[2] + c.direction[2] * d};
  };
  // Rows vmin..vmax the points cover, false if one is off the frame.
  double vmin = 0, vmax = 0;
  auto fits = [&](double d, double tilt) {
    place(d, tilt);
    const double m = o.margin / 2;
    vmin = 1, vmax = 0;
    for (const Vec3& p : points) {
      double u, v;
      if (!c.project(p, u, v) || u < m || u > 1 - m || v < m || v > 1 - m) return false;
      vmin = std::min(vmin, v), vmax = std::max(vmax, v);
    }
    return true;
  };
  auto row_angle = [&](double v) { return std::atan((v - 0.5) * 2 * t / o.aspect); };
  // Tilt so the middle of what is seen lands on row center_v, then fit the
  // distance; the middle moves as the distance changes, so repeat a few times.
  double tilt = row_angle(o.center_v), dist = size;
  for (int round = 0; round < 6; ++round) {
    // Farther always fits better (every point tends to the centre's row), so
    // bisect the distance between a too-near and a fitting one.
    double near = 0, far = size;
    while (!fits(far, tilt) && far < size * 1e6) near = far, far *= 2;
    for (int i = 0; i < 40; ++i) {
      const double mid = (near + far) / 2;
      (fits(mid, tilt) ? far : near) = mid;
    }
    dist = far;
    fits(dist, tilt);
    const double shift = row_angle((vmin + vmax) / 2) - row_angle(o.center_v);
    if (std::abs(shift) < 1e-4 || round == 5) break;  // keep the tilt the distance was fitted for
    tilt -= shift;
  }
  place(std::max(dist, 1e-3 * size) * o.distance_scale, tilt);
  return c;
}

Camera frame_box(const Vec3& lo, const Vec3& hi, const CameraOptions& o) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  return frame_points(corners, o);
}

Camera camera_from_pose(const CameraPose& pose) {
  for (const auto& [name, w] : {std::pair{"camera_location", pose.location}, {"camera_direction", pose.direction},
                                {"camera_right", pose.right}, {"camera_up", pose.up}})
    for (double x : w) check_finite(name, x);
  Camera c;
  c.given = true;
  c.location = to_pov(pose.location);
  c.given_direction = to_pov(pose.direction);
  c.given_right = to_pov(pose.right);
  c.given_up = to_pov(pose.up);
  const double dn = norm(c.given_direction), rn = norm(c.given_right), un = norm(c.given_up);
  // A flat triple sees the world as a line: refused, with room for the
  // rounding of nearly perpendicular vectors.
  if (!(std::abs(det(c.given_direction, c.given_right, c.given_up)) > 1e-9 * dn * rn * un))
    invalid("the given camera's direction, right and up must span space (none zero, no two parallel)");
  c.direction = unit(c.given_direction);
  c.right = unit(c.given_right);
  c.up = unit(c.given_up);
  c.fov_deg = 2 * std::atan(0.5 * rn / dn) * 180 / std::numbers::pi;
  c.aspect = rn / un;
  c.look_at = {c.location[0] + c.given_direction[0], c.location[1] + c.given_direction[1],
               c.location[2] + c.given_direction[2]};
  return c;
}

std::string camera_sdl(const Camera& c) {
  if (c.given)
    return "camera {\n  perspective\n  location " + vec(c.location) + "\n  right " + vec(c.given_right) +
           "\n  up " + vec(c.given_up) + "\n  direction " + vec(c.given_direction) +
           "\n  // render at an aspect of " + number(c.aspect) + ", as this camera was given\n}\n\n";
  return "camera {\n  perspective\n  location " + vec(c.location) + "\n  sky " + vec(c.up) +
         "\n  right x*image_width/image_height\n  angle " + number(c.fov_deg) + "\n  look_at " +
         vec(c.look_at) + "\n}\n\n";
}

}  // namespace ft::pov
