// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/planet_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "povray/mesh2_export.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov {

double planet_max_gradient(const Heightfield& map, double span, double min_radius) {
  const HeightStats st = map.stats();
  const double range = st.max - st.min;
  if (!(range > 0)) return 1.1;
  const int32_t w = map.width(), h = map.height();
  const double dlon = 2 * std::numbers::pi / w, dlat = std::numbers::pi / h;
  double g = 0;
  for (int32_t y = 0; y < h; ++y) {
    const double lat = (90.0 - (y + 0.5) * 180.0 / h) * std::numbers::pi / 180;
    const double ew = dlon * std::max(std::cos(lat), 1e-3) * min_radius, ns = dlat * min_radius;
    for (int32_t x = 0; x < w; ++x) {
      const double v = map.at(x, y);
      g = std::max(g, std::fabs(map.at((x + 1) % w, y) - v) / ew);
      if (y + 1 < h) g = std::max(g, std::fabs(map.at(x, y + 1) - v) / ns);
    }
  }
  // Heights in scene units: span / range per map unit. 1.3: the margin POV-Ray's docs advise.
  return 1.3 * (1.0 + g * span / range);
}

namespace {

void check_scene(const PlanetScene& s) {
  if (!(s.exaggeration > 0) || !std::isfinite(s.exaggeration))
    invalid("the height exaggeration must be a finite number > 0, got " + format_number(s.exaggeration));
  if (!(s.distance > 1.2) || !std::isfinite(s.distance))
    invalid("the camera distance must be more than 1.2 radii, got " + format_number(s.distance));
  check_range("view latitude", s.view_latitude_deg, -90, 90);
  check_finite("view longitude", s.view_longitude_deg);
}

// The scene around the ground: ft_planet.inc, camera, light and background
// before `ground` (SDL), the sea and the atmosphere after it.
std::string globe_scene(const PlanetScene& s, const std::string& file_name, const std::string& ground) {
  const double k = s.exaggeration / s.radius;  // metres -> scene units (radius 1)
  // The camera: POV-Ray's north is +y; image_map map_type 1 puts the map's
  // left edge (longitude -180) towards -z... seen from above the view point.
  const double lat = s.view_latitude_deg * std::numbers::pi / 180, lon = s.view_longitude_deg * std::numbers::pi / 180;
  const Vec3 dir{std::cos(lat) * std::sin(lon), std::sin(lat), -std::cos(lat) * std::cos(lon)};
  const Vec3 cam{dir[0] * s.distance, dir[1] * s.distance, dir[2] * s.distance};
  const double angle = 2.4 * std::asin(1.0 / s.distance) * 180 / std::numbers::pi;  // the globe fills ~80 %

  std::string t;
  t += "// fracterra planet: radius " + number(s.radius) + " m, heights x " + number(s.exaggeration) +
       "; scene units: the radius is 1\n";
  t += "// Render: povray +W800 +H600 +A0.1 " + comment_text(file_name) + "\n";
  t += "#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 8 }\n\n";
  t += "// ---- povray_macros/ft_planet.inc, embedded so the scene stands alone ----\n";
  t += kFtPlanetInc;
  t += "// ---- end of ft_planet.inc ----\n\n";
  t += "camera { perspective location " + vec(cam) + " look_at <0, 0, 0> right x * image_width / image_height angle " +
       number(angle) + " }\n";
  t += "light_source { " + vec({40 * dir[0] + 30, 40 * dir[1] + 25, 40 * dir[2] - 20}) + " color rgb 1.3 }\n";
  t += "background { rgb <0.005, 0.005, 0.012> }\n\n";
  t += ground;
  if (!std::isnan(s.sea_height)) t += "FT_Planet_Sea(1, " + number(s.sea_height * k) + ")\n";
  if (s.atmosphere) t += "FT_Planet_Atmosphere(1, 0.04)\n";
  return t;
}

}  // namespace

void write_planet_scene(const Heightfield& map, const PlanetScene& s, const std::string& pov_path) {
  check_scene(s);
  io::AtomicFile out(pov_path);  // fails now, before the PNG, if the folder is unwritable
  const std::string png_path = platform::sibling_path(pov_path, "_height.png");
  const std::string png = platform::file_name_of(png_path);
  io::write_heightfield(map, png_path);

  const HeightStats st = map.stats();
  const double k = s.exaggeration / s.radius;  // metres -> scene units (radius 1)
  const double hmin = st.min * k, hmax = st.max * k;
  const double gradient = planet_max_gradient(map, hmax - hmin, 1.0 + std::min(0.0, hmin));
  out.write(globe_scene(s, platform::file_name_of(pov_path),
                        "FT_Planet(" + quoted(png) + ", 1, " + number(hmin) + ", " + number(hmax) + ", " +
                            number(gradient) + ")\n"));
  out.commit();
}

Mesh pov_globe_mesh(const Mesh& mesh, double radius) {
  Mesh out;
  out.positions.resize(mesh.positions.size());
  const double k = 1.0 / radius;
  for (size_t i = 0; i < mesh.positions.size(); i += 3) {
    // planet.h's (x, y, z), z north, to POV-Ray's axes, y north, as image_map
    // map_type 1 lays the isosurface's map (u from +x towards +z, so the map's
    // left edge, longitude -180, at +x): both geometries are the same globe.
    out.positions[i] = float(-mesh.positions[i] * k);
    out.positions[i + 1] = float(mesh.positions[i + 2] * k);
    out.positions[i + 2] = float(-mesh.positions[i + 1] * k);
  }
  // That is a reflection: each face reversed stays counter-clockwise seen from
  // outside, so mesh2's normals (from the winding) point out.
  out.face_sizes = mesh.face_sizes;
  out.face_indices.resize(mesh.face_indices.size());
  size_t first = 0;
  for (int32_t n : mesh.face_sizes) {
    std::reverse_copy(mesh.face_indices.begin() + std::ptrdiff_t(first),
                      mesh.face_indices.begin() + std::ptrdiff_t(first + size_t(n)),
                      out.face_indices.begin() + std::ptrdiff_t(first));
    first += size_t(n);
  }
  return out;
}

void write_planet_mesh_scene(const Mesh& mesh, const std::vector<float>& heights, const PlanetScene& s,
                             const std::string& pov_path) {
  check_scene(s);
  if (heights.empty() || heights.size() != mesh.vertex_count())
    invalid("the planet mesh needs one height per vertex");
  io::AtomicFile out(pov_path);  // fails now, before the mesh, if the folder is unwritable
  const std::string inc_path = platform::sibling_path(pov_path, "_mesh.inc");
  const std::string inc = platform::file_name_of(inc_path);
  write_mesh2(pov_globe_mesh(mesh, s.radius), inc_path, "FT_Planet_Mesh2");
  const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
  const double k = s.exaggeration / s.radius;
  out.write(globe_scene(s, platform::file_name_of(pov_path),
                        "#include " + quoted(inc) + "\nFT_Planet_Mesh(FT_Planet_Mesh2, 1, " + number(*lo * k) +
                            ", " + number(*hi * k) + ")\n"));
  out.commit();
}

}  // namespace ft::pov
