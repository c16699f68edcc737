// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/scene_materials.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3 scaled(const Vec3& v, double k) { return {v[0] * k, v[1] * k, v[2] * k}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 unit(const Vec3& v) { return scaled(v, 1 / norm(v)); }
double degrees(double r) { return r * 180 / kPi; }

// Where Cycles' smooth spot edge begins: its smoothstep runs over the top
// `blend` share of the cone's cosine range, from cos(half angle) up to 1.
double spot_inner_deg(const SceneLight& l) {
  const double c = std::cos(l.spot_size_deg * kPi / 360);
  return degrees(std::acos(std::min(1.0, c + (1 - c) * l.spot_blend)));
}

// Principled's GGX of roughness r has alpha = r^2; Blinn's exponent of the
// same width is 2 / alpha^2 - 2 (Walter et al. 2007), POV-Ray's roughness
// its inverse. The highlight's energy matches when POV-Ray's peak is
// F0 (n + 1) / 8 (its lobe integrates to 8 pi / (n + 1) times the peak).
struct Highlight {
  double specular, roughness;
};
Highlight highlight_of(const SceneMaterial& m) {
  const double alpha = std::max(m.roughness * m.roughness, 1e-3);
  const double n = std::max(2 / (alpha * alpha) - 2, 1.0);
  return {0.08 * m.specular * (n + 1) / 8, 1 / n};
}

}  // namespace

void validate_light(const SceneLight& l) {
  if (l.kind != LightKind::kSun && l.kind != LightKind::kPoint && l.kind != LightKind::kSpot &&
      l.kind != LightKind::kArea)
    invalid("light kind must be 0 (sun), 1 (point), 2 (spot) or 3 (area), got " + std::to_string(int(l.kind)));
  for (int k = 0; k < 3; ++k) {
    check_range("light color", l.color[size_t(k)], 0, 1000);
    check_finite("light location", l.location[size_t(k)]);
    check_finite("light direction", l.direction[size_t(k)]);
    check_finite("light area_u", l.area_u[size_t(k)]);
    check_finite("light area_v", l.area_v[size_t(k)]);
  }
  check_range("light power", l.power, 0, 1e12);
  if (l.kind != LightKind::kPoint && !(norm(l.direction) > 0))
    invalid("a sun, spot or area light needs a direction that is not zero");
  if (l.kind == LightKind::kSpot) {
    check_range("spot_size_deg", l.spot_size_deg, 1, 180);
    check_range("spot_blend", l.spot_blend, 0, 1);
    check_range("spot_cos_power", l.spot_cos_power, 0, 100);
  }
  if (l.kind == LightKind::kArea && !(norm(l.area_u) > 0 && norm(l.area_v) > 0))
    invalid("an area light needs sides area_u and area_v that are not zero");
}

void validate_material(const SceneMaterial& m, const char* what) {
  const std::string w = what;
  for (int k = 0; k < 3; ++k) {
    check_range((w + " color").c_str(), m.color[size_t(k)], 0, 1);
    check_range((w + " emission").c_str(), m.emission[size_t(k)], 0, 1e6);
  }
  check_range((w + " roughness").c_str(), m.roughness, 0, 1);
  check_range((w + " specular").c_str(), m.specular, 0, 1);
}

Vec3 light_color(const SceneLight& l, double fade) {
  // A white surface facing the light: Cycles returns its irradiance E over
  // pi; POV-Ray returns the colour times its fading, 2 D^2 / d^2 far from it.
  //   sun      E = S                         C = S / pi
  //   point    E = P / (4 pi d^2)            C = P / (8 pi^2 D^2)
  //   spot     the point's, in its cone
  //   area     E = P / (pi d^2) on its axis  C = P / (2 pi^2 D^2)
  // (an area light is a Lambertian emitter of flux P: its intensity on its
  // axis is P / pi; docs/povray.md.)
  double k = l.power / kPi;
  if (l.kind == LightKind::kPoint || l.kind == LightKind::kSpot) k = l.power / (8 * kPi * kPi * fade * fade);
  if (l.kind == LightKind::kArea) k = l.power / (2 * kPi * kPi * fade * fade);
  return scaled(l.color, k);
}

std::string light_sdl(const SceneLight& l, const Vec3& centre, double extent) {
  const double fade = kFadeDistanceShare * extent;
  const Vec3 dir = l.kind == LightKind::kPoint ? Vec3{0, 0, -1} : unit(to_pov(l.direction));
  const std::string color = "  color rgb " + vec(light_color(l, fade)) + "\n";
  const std::string shadows = l.shadows ? "" : "  shadowless\n";
  if (l.kind == LightKind::kSun)
    return "light_source {\n  " + vec(plus(centre, scaled(dir, -100 * extent))) + "\n" + color +
           "  parallel point_at " + vec(centre) + "\n" + shadows + "}\n";
  const Vec3 at = to_pov(l.location);
  std::string s = "light_source {\n  " + vec(at) + "\n" + color + "  fade_distance " + number(fade) +
                  " fade_power 2\n";
  if (l.kind == LightKind::kSpot)
    s += "  spotlight point_at " + vec(plus(at, dir)) + " radius " + number(spot_inner_deg(l)) + " falloff " +
         number(l.spot_size_deg / 2) + " tightness " + number(l.spot_cos_power) + "\n";
  if (l.kind == LightKind::kArea) {
    // A grid of point lights sharing the colour, each falling off with the
    // cosine from the face's normal as a Lambertian emitter does; one-sided.
    s += "  area_light " + vec(to_pov(l.area_u)) + ", " + vec(to_pov(l.area_v)) + ", 5, 5 adaptive 1" +
         (l.area_ellipse ? " circular" : "") + "\n";
    s += "  spotlight point_at " + vec(plus(at, dir)) + " radius 90 falloff 90 tightness 1\n";
  }
  return s + shadows + "}\n";
}

std::string material_texture_sdl(const SceneMaterial& m, bool ambient) {
  const double top = std::max({m.emission[0], m.emission[1], m.emission[2]});
  const bool emitter = top > 0 && std::max({m.color[0], m.color[1], m.color[2]}) == 0;
  // POV-Ray's emission is the pigment times a colour: a pure emitter is
  // painted in its emission's hue; otherwise the base colour carries both.
  Vec3 pigment = emitter ? scaled(m.emission, 1 / top) : m.color;
  std::string finish;
  if (emitter) {
    finish = "ambient 0 diffuse 0 emission " + number(top);
  } else {
    const Highlight h = highlight_of(m);
    finish = std::string(ambient ? "ambient 1 " : "") + "diffuse 1 specular " + number(h.specular) + " roughness " +
             number(h.roughness);
    if (top > 0) {
      Vec3 e;
      for (size_t k = 0; k < 3; ++k) e[k] = m.emission[k] / std::max(pigment[k], 1e-3);
      for (size_t k = 0; k < 3; ++k) pigment[k] = std::max(pigment[k], 1e-3);
      finish += " emission rgb " + vec(e);
    }
    // A glossy surface mirrors its surroundings with Fresnel (its interior's
    // index); a rough one's blurred reflection is left out.
    if (m.water || m.roughness < 0.3) finish += " reflection { 0, 1 fresnel on }";
  }
  return "texture { pigment { rgb " + vec(pigment) + " } finish { " + finish + " } }";
}

std::string material_interior_sdl(const SceneMaterial& m) {
  const double f0 = std::sqrt(std::clamp(0.08 * m.specular, 1e-4, 0.64));
  return "interior { ior " + number((1 + f0) / (1 - f0)) + " }";
}

std::string material_sdl(const SceneMaterial& m, bool ambient) {
  if (m.water) return "material { FT_Water_Material }";
  return "material { " + material_texture_sdl(m, ambient) + " " + material_interior_sdl(m) + " }";
}

}  // namespace ft::pov
