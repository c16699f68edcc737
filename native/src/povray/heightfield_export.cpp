// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/heightfield_export.hpp"

#include <cmath>

#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov {

void validate_terrain(const Heightfield& hf, double world_size_x, double world_size_y, double vertical_scale) {
  check_positive("terrain world_size_x", world_size_x);
  check_positive("terrain world_size_y", world_size_y);
  check_positive("terrain vertical_scale", vertical_scale);
  if (hf.width() < 2 || hf.height() < 2)
    invalid("a POV-Ray height_field needs at least 2 x 2 samples, got " + std::to_string(hf.width()) +
            " x " + std::to_string(hf.height()));
}

TerrainPlacement place_terrain(const Heightfield& hf, double world_size_x, double world_size_y,
                               double vertical_scale) {
  validate_terrain(hf, world_size_x, world_size_y, vertical_scale);
  const HeightStats s = hf.stats();
  if (!std::isfinite(s.min) || !std::isfinite(s.max))
    invalid("the terrain holds NaN or infinite samples");
  TerrainPlacement p;
  p.world_size_x = world_size_x;
  p.world_size_y = world_size_y;
  p.vertical_scale = vertical_scale;
  p.z_min = s.min * vertical_scale;
  p.z_max = s.max * vertical_scale;
  p.width = hf.width();
  p.height = hf.height();
  return p;
}

TerrainPlacement write_heightfield_png(const Heightfield& hf, const std::string& png_path,
                                       double world_size_x, double world_size_y, double vertical_scale) {
  TerrainPlacement p = place_terrain(hf, world_size_x, world_size_y, vertical_scale);
  io::write_png(png_path, io::heightfield_to_image(hf));
  return p;
}

double pov_height_scale(const TerrainPlacement& place) {
  const double range = place.z_max - place.z_min;
  // A flat terrain is all-zero pixels; any positive scale puts it at z_min.
  return (range > 0 ? range : 1.0) * (65536.0 / 65535.0);
}

std::string heightfield_sdl(const std::string& png_ref, const TerrainPlacement& place, double water_z,
                            const std::string& modifiers) {
  const double sy = pov_height_scale(place);
  std::string s = "height_field {\n  png " + quoted(png_ref) + "\n  smooth\n";
  if (std::isfinite(water_z)) {
    const double level = (water_z - place.z_min) / sy;
    if (level > 0) s += "  water_level " + number(std::min(level, 1.0)) + "\n";
  }
  // POV-Ray puts image row 0 at z = 1; fracterra's row 0 is y = 0, so the
  // unit box is mirrored in z before it is scaled to real units.
  s += "  scale <1, 1, -1> translate <0, 0, 1>\n";
  s += "  scale " + vec({place.world_size_x, sy, place.world_size_y}) + "\n";
  s += "  translate " + vec({0, place.z_min, 0}) + "\n";
  s += modifiers;
  s += "}\n";
  return s;
}

}  // namespace ft::pov
