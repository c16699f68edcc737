#include "povray/camera.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace ft::pov {
namespace {

constexpr double kPi = 3.14159265358979323846;
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

}  // namespace

void validate_camera_options(const CameraOptions& o) {
  check_range("camera azimuth_deg", o.azimuth_deg, -360, 360);
  check_range("camera elevation_deg", o.elevation_deg, 1, 90);
  check_range("camera fov_deg", o.fov_deg, 5, 150);
  check_range("camera aspect", o.aspect, 0.1, 10);
  check_range("camera margin", o.margin, 0, 0.5);
  check_range("camera distance_scale", o.distance_scale, 0.1, 100);
}

bool Camera::project(const Vec3& p, double& u, double& v) const {
  const Vec3 d{p[0] - location[0], p[1] - location[1], p[2] - location[2]};
  const double depth = dot(d, direction);
  if (depth <= 0) return false;
  // POV-Ray: the image plane spans |right| = aspect across and |up| = 1
  // down, at distance 0.5 * aspect / tan(angle / 2).
  const double t = std::tan(fov_deg * kPi / 360);
  u = 0.5 + dot(d, right) / depth * 0.5 / t;
  v = 0.5 - dot(d, up) / depth * 0.5 * aspect / t;
  return true;
}

Camera frame_box(const Vec3& lo, const Vec3& hi, const CameraOptions& o) {
  validate_camera_options(o);
  Camera c;
  c.fov_deg = o.fov_deg;
  c.aspect = o.aspect;
  c.look_at = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const double az = o.azimuth_deg * kPi / 180, el = o.elevation_deg * kPi / 180;
  // World azimuth: 0 = +y (POV +z), 90 = +x; the camera looks back along it.
  const Vec3 to_camera{std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
  c.direction = {-to_camera[0], -to_camera[1], -to_camera[2]};
  // Straight down needs another sky; POV-Ray's default sky is y.
  const Vec3 sky = o.elevation_deg > 89.9 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  c.right = unit(cross(sky, c.direction));
  c.up = cross(c.direction, c.right);
  const double th = std::tan(o.fov_deg * kPi / 360) * (1 - o.margin);
  const double tv = th / o.aspect;
  // Each corner q fits when |q.right| <= th * (d + q.dir) and the same for up.
  double dist = 0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 q{(i & 1 ? hi[0] : lo[0]) - c.look_at[0], (i & 2 ? hi[1] : lo[1]) - c.look_at[1],
                 (i & 4 ? hi[2] : lo[2]) - c.look_at[2]};
    const double along = dot(q, c.direction);
    dist = std::max({dist, std::abs(dot(q, c.right)) / th - along, std::abs(dot(q, c.up)) / tv - along});
  }
  const double size = std::sqrt(dot({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]},
                                    {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}));
  dist = std::max(dist, 1e-3 * size + 1e-9) * o.distance_scale;
  c.location = {c.look_at[0] + to_camera[0] * dist, c.look_at[1] + to_camera[1] * dist,
                c.look_at[2] + to_camera[2] * dist};
  return c;
}

}  // namespace ft::pov
