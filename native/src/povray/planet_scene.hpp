// SPDX-License-Identifier: GPL-3.0-or-later
// A POV-Ray scene of a fractal planet (`fracterra planet --pov`): the
// equirectangular height map as a 16-bit PNG beside the scene, read by
// ft_planet.inc's FT_Planet isosurface (image_map map_type 1), or the exact
// cube-sphere as a mesh2 beside it (FT_Planet_Mesh); a sea sphere and an
// atmosphere. Scene units: the radius is 1; heights are exaggerated.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include <vector>

#include "core/heightfield.hpp"
#include "core/mesh.hpp"

namespace ft::pov {

struct PlanetScene {
  double radius = 6371000.0;   // metres: the map's heights are metres above it
  double sea_height = std::numeric_limits<double>::quiet_NaN();  // metres, NaN: no sea
  double exaggeration = 20.0;  // heights x this, > 0
  double view_latitude_deg = 25.0, view_longitude_deg = 20.0;  // the camera looks at this point of the globe
  double distance = 3.2;       // camera distance from the centre in radii, > 1.2
  bool atmosphere = true;
};

// The largest |gradient| of FT_Planet's function for this map (radial 1 plus
// the height's change between neighbouring pixels over their distance on
// the sphere), with a margin: POV-Ray's isosurface misses surface beyond it.
double planet_max_gradient(const Heightfield& map, double span, double min_radius);

// Writes the map as `<scene stem>_height.png` beside `pov_path` and the
// scene itself (atomically). The map must be equirectangular (planet.h).
void write_planet_scene(const Heightfield& map, const PlanetScene& s, const std::string& pov_path);

// The planet's mesh (metres, planet.h's axes: cube_sphere_mesh with the
// scene's exaggeration as its vertical scale) in scene units and POV-Ray's
// axes, the same globe the isosurface's map gives, faces facing out.
Mesh pov_globe_mesh(const Mesh& mesh, double radius);

// Writes the mesh as a mesh2 in `<scene stem>_mesh.inc` beside `pov_path`
// and the scene (atomically); `heights`: the mesh's, metres (for the colours).
void write_planet_mesh_scene(const Mesh& mesh, const std::vector<float>& heights, const PlanetScene& s,
                             const std::string& pov_path);

extern const char* const kFtPlanetInc;

}  // namespace ft::pov
