// SPDX-License-Identifier: GPL-3.0-or-later
// Another program's lights and materials (Blender's Cycles) as POV-Ray SDL,
// by the conversions docs/povray.md states, so the same scene renders alike:
// POV-Ray lights a white diffuse 1 surface facing a light of colour C to C,
// where Cycles returns the irradiance E over pi; so each light's colour is
// the E / pi it gives such a surface.
#pragma once

#include <string>

#include "povray/scene.hpp"

namespace ft::pov {

// POV-Ray's inverse-square fading, 2 / (1 + (d / D)^2), is 2 D^2 / d^2 to a
// relative (D / d)^2: with D this fraction of the scene's extent the law is
// exact to 1e-6 across the scene.
constexpr double kFadeDistanceShare = 1e-3;

// The light_source statement of `l` (world axes) in a scene spanning
// `extent` around `centre` (POV axes; a sun is placed 100 extents away).
std::string light_sdl(const SceneLight& l, const Vec3& centre, double extent);
// The POV-Ray colour of `l`'s light_source: what the rules above give.
Vec3 light_color(const SceneLight& l, double fade_distance);

// `texture { ... }` of `m`; `ambient`: the sky's even light (ambient_light),
// which a surface returns in full under a scene's own light.
std::string material_texture_sdl(const SceneMaterial& m, bool ambient);
// `interior { ior n }`: the index the specular gives (F0 = 0.08 specular =
// ((n - 1) / (n + 1))^2), for reflections with Fresnel.
std::string material_interior_sdl(const SceneMaterial& m);
// `material { texture {...} interior {...} }` of `m` (water: FT_Water_Material).
std::string material_sdl(const SceneMaterial& m, bool ambient);

void validate_light(const SceneLight& l);
void validate_material(const SceneMaterial& m, const char* what);

}  // namespace ft::pov
