#include "povray/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "io/png_image.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"
#include "splat/splat_map.hpp"

namespace ft::pov {
namespace {


void grow(Vec3& lo, Vec3& hi, const Vec3& p) {
  for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
}

std::string default_image_path(const std::string& pov_path) {
  std::filesystem::path p = platform::fs_path(pov_path);
  return platform::utf8_of(p.replace_extension(".terrain.png"));
}

const char* kind_name(LineKind k) {
  switch (k) {
    case LineKind::kLightning: return "lightning";
    case LineKind::kCoastline: return "coastline";
    default: return "line";
  }
}

double median(std::vector<double>& v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The file's vertex radii as taper only: `base` times each radius over the
// set's largest (0 = `base`).
PolylineSet tapered(const PolylineSet& set, double base) {
  PolylineSet out = set;
  double top = 0;
  for (double r : set.radii) top = std::max(top, r);
  for (double& r : out.radii) r = top > 0 && r > 0 ? base * (r / top) : base;
  return out;
}

// "x.pov" -> "x.colors.png", or beside a given terrain image: "t.png" -> "t.colors.png".
std::string colors_image_path(const std::string& pov_path, const std::string& image_path) {
  std::filesystem::path p = platform::fs_path(image_path.empty() ? pov_path : image_path);
  return platform::utf8_of(p.replace_extension(".colors.png"));
}

// The terrain colours as an 8-bit sRGB PNG (sRGB spends its 256 steps where
// the eye tells them apart; POV-Ray decodes it with `gamma srgb`).
void write_colors_png(const std::string& path, const Heightfield& hf, const float* rgb) {
  const size_t n = size_t(hf.width()) * size_t(hf.height()) * 3;
  std::vector<uint8_t> bytes(n);
  for (size_t i = 0; i < n; ++i) {
    const double c = std::clamp(double(rgb[i]), 0.0, 1.0);
    const double e = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
    bytes[i] = uint8_t(std::lround(255 * e));
  }
  io::write_png_rgb(path, hf.width(), hf.height(), bytes.data());
}

// The texture painting `place`'s terrain with the colours PNG `ref`: the
// image lies on x-y with row 0 on top; it is turned onto x-z with row 0 at
// z = 0 (as the height_field), projected down y, and stretched half a pixel
// past each edge so pixel centres land on the samples.
std::string colors_texture_sdl(const std::string& ref, const TerrainPlacement& place, bool scene_light) {
  const double w = place.width, h = place.height, sx = place.world_size_x, sy = place.world_size_y;
  return "  texture {\n    pigment {\n      image_map { png " + quoted(ref) + " gamma srgb interpolate 2 }\n" +
         "      scale <1, -1, 1> translate y rotate 90*x\n      scale " +
         vec({w / (w - 1) * sx, 1, h / (h - 1) * sy}) + "\n      translate " +
         vec({-0.5 * sx / (w - 1), 0, -0.5 * sy / (h - 1)}) + "\n    }\n" +
         // Under scene light the sky's ambient is the even light of a sky
         // dome, which a surface returns in full; else POV-Ray's default.
         (scene_light ? "    finish { ambient 1 diffuse 1 }\n" : "    finish { diffuse 1 }\n") + "  }\n";
}

}  // namespace

// A tube thinner than about a pixel breaks up into dots; one much thicker
// than the smallest detail the image resolves (a pixel) hides it: 16385
// points of an FPL at a radius of 1% of the line were a smooth beaded worm.
// So the radius is 0.75 pixel at the distance of the lines (a tube 1.5 px
// wide), or a tenth of the median segment where that is larger (coarse
// lines: Koch depth 3 reads as a tube, not a hairline), but never more than
// the kind's style cap, the fixed fractions of the scene used before.
double automatic_line_radius(const SceneLines& l, const Camera& cam, double extent, int32_t image_width) {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  std::vector<double> seg;
  for (int64_t i = 0; i < l.set->line_count(); ++i)
    for (int64_t v = l.set->line_begin(i); v < l.set->line_end(i); ++v) {
      const Vec3& a = l.set->points[size_t(v)];
      grow(lo, hi, to_pov(a));
      if (v + 1 < l.set->line_end(i)) {
        const Vec3& b = l.set->points[size_t(v + 1)];
        const double d = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
        if (d > 0) seg.push_back(d);
      }
    }
  const double cap = (l.kind == LineKind::kLightning   ? 0.0035
                      : l.kind == LineKind::kCoastline ? 0.0012
                                                       : 0.003) * extent;
  double pixel = 0;
  if (lo[0] <= hi[0]) {
    const Vec3 c{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    const double d = std::hypot(c[0] - cam.location[0], c[1] - cam.location[1], c[2] - cam.location[2]);
    pixel = 2 * d * std::tan(cam.fov_deg * std::numbers::pi / 360) / image_width;
  }
  const double m = median(seg);
  return std::max(0.75 * pixel, std::isnan(m) ? cap : std::min(0.1 * m, cap));
}

void validate_scene_params(const SceneParams& p) {
  if (p.terrain) validate_terrain(*p.terrain, p.world_size_x, p.world_size_y, p.vertical_scale);
  // sea_level, the sun and the camera are checked once, by
  // ft_pov_scene_params' table (pov_params.cpp), before they get here.
  for (const auto& l : p.lines) {
    check_not_null("polyline set", l.set);
    if (l.kind != LineKind::kGeneric && l.kind != LineKind::kLightning && l.kind != LineKind::kCoastline)
      invalid("polyline kind must be 0 (line), 1 (lightning) or 2 (coastline), got " +
              std::to_string(int(l.kind)));
    if (!(l.radius >= 0) || !std::isfinite(l.radius))
      invalid("polyline radius must be finite and >= 0 (0 = automatic), got " + format_number(l.radius));
    check_positive("polyline radius_scale", l.radius_scale);
  }
  check_int_range("image_width", p.image_width, 16, 16384);
  if (p.terrain_colors) {
    if (!p.terrain || p.tiles) invalid("terrain colours need a terrain of one piece (not tiles)");
    const size_t n = size_t(p.terrain->width()) * size_t(p.terrain->height()) * 3;
    for (size_t i = 0; i < n; ++i)
      if (!(p.terrain_colors[i] >= 0) || !std::isfinite(p.terrain_colors[i]))
        invalid("terrain colours must be finite and >= 0 (linear RGB, above 1 is clipped), got " +
                format_number(p.terrain_colors[i]) + " at value " + std::to_string(i));
  }
  for (int k = 0; k < 3; ++k) {
    check_range("sky_color", p.sky_color[size_t(k)], 0, 1000);
    check_range("sun_color", p.sun_color[size_t(k)], 0, 1000);
  }
  if (!p.terrain && p.lines.empty()) invalid("a scene needs a terrain or at least one polyline set");
  for (const SceneLake& l : p.lakes) {
    check_finite("lake level", l.level);
    for (const auto& ring : l.rings)
      if (ring.size() < 4) invalid("a lake's shoreline ring needs at least 4 points (closed), got " + std::to_string(ring.size()));
  }
}

double auto_camera_elevation(const SceneParams& p) {
  if (p.terrain || p.tiles) return kTerrainElevationDeg;
  bool all_lightning = !p.lines.empty();
  for (const auto& l : p.lines) all_lightning = all_lightning && l.kind == LineKind::kLightning;
  return all_lightning ? kLightningElevationDeg : kLinesElevationDeg;
}

SceneSummary write_scene(const SceneParams& p, const std::string& pov_path) {
  validate_scene_params(p);
  io::AtomicFile out(pov_path);  // fails now, before the PNG, if the folder is unwritable
  bool stormy = false;
  for (const auto& l : p.lines) stormy = stormy || l.kind == LineKind::kLightning;
  const std::string folder = folder_of(pov_path);
  SceneSummary sum;
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  const double water = p.has_sea ? p.sea_level : NAN;

  // What the camera frames (POV axes): the land above the sea on a 65 x 65
  // lattice of the terrain, and every polyline vertex.
  std::vector<Vec3> frame;
  if (p.terrain) {
    sum.terrain = place_terrain(*p.terrain, p.world_size_x, p.world_size_y, p.vertical_scale);
    const Heightfield& hf = *p.terrain;
    std::vector<Vec3> under;
    for (int j = 0; j <= 64; ++j)
      for (int i = 0; i <= 64; ++i) {
        const int x = int(std::lround(i * (hf.width() - 1) / 64.0)), y = int(std::lround(j * (hf.height() - 1) / 64.0));
        const Vec3 q{x * p.world_size_x / (hf.width() - 1), hf.at(x, y) * p.vertical_scale, y * p.world_size_y / (hf.height() - 1)};
        (p.has_sea && q[1] < water ? under : frame).push_back(q);
      }
    if (frame.empty())
      for (Vec3 q : under) frame.push_back({q[0], water, q[2]});  // all under the sea
  }
  for (const auto& l : p.lines)
    for (const Vec3& w : l.set->points) {
      Vec3 q = to_pov(w);
      if (l.kind == LineKind::kCoastline && p.has_sea) q[1] = water;
      frame.push_back(q);
    }
  if (frame.empty()) invalid("the scene is empty: the polyline sets hold no vertices");
  for (const Vec3& q : frame) grow(lo, hi, q);
  const double extent = std::max({hi[0] - lo[0], hi[2] - lo[2], hi[1] - lo[1], 1e-9});
  sum.lo = lo;
  sum.hi = hi;
  CameraOptions camera = p.camera;
  if (camera.elevation_deg == 0) camera.elevation_deg = auto_camera_elevation(p);
  sum.camera = p.camera_given ? camera_from_pose(p.camera_pose) : frame_points(frame, camera);
  const Camera& cam = sum.camera;
  // The lights aim at the framed camera's target, or the content's middle.
  const Vec3 centre =
      p.camera_given ? Vec3{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2} : cam.look_at;

  std::string s;
  s += "// fracterra scene" + (p.title.empty() ? std::string() : ": " + comment_text(p.title)) + "\n";
  s += "// Render: fracterra render " + comment_text(platform::utf8_of(platform::fs_path(pov_path).filename())) +
       " --width 800 --height 600 --out image.png\n";
  s += "//     or: povray +W800 +H600 +A0.1 " +
       comment_text(platform::utf8_of(platform::fs_path(pov_path).filename())) + "\n";
  s += "// Axes: fracterra world (x, y, z up) is POV-Ray <x, z, y>; units are world units.\n";
  s += "#version 3.7;\n";
  s += "global_settings { assumed_gamma 1.0 max_trace_level 6" +
       (p.scene_light ? " ambient_light rgb " + vec(p.sky_color) : std::string()) + " }\n\n";
  s += "#ifndef(FT_Texture_Scale) #declare FT_Texture_Scale = " + number(extent / 200) + "; #end\n";
  s += "// ---- povray_macros/ft_terrain.inc, embedded so the scene stands alone ----\n";
  s += kFtTerrainInc;
  s += "// ---- end of ft_terrain.inc ----\n\n";
  s += std::string("#ifndef(FT_Stormy) #declare FT_Stormy = ") + (stormy ? "1" : "0") + "; #end\n";
  s += "// ---- povray_macros/ft_scene_materials.inc, embedded ----\n";
  s += kFtSceneMaterialsInc;
  s += "// ---- end of ft_scene_materials.inc ----\n";
  if (p.rivers || !p.lakes.empty()) {
    s += "#declare FT_Water_Embedded = 1;\n// ---- povray_macros/ft_water.inc, embedded ----\n";
    s += kFtWaterInc;
    s += "// ---- end of ft_water.inc ----\n";
  }
  s += "\n#declare FT_Scene_Min = " + vec(lo) + ";\n#declare FT_Scene_Max = " + vec(hi) + ";\n\n";

  s += camera_sdl(cam);

  const double saz = p.sun_azimuth_deg * std::numbers::pi / 180, sel = p.sun_elevation_deg * std::numbers::pi / 180;
  const double far = extent * 100;
  const Vec3 sun{centre[0] + far * std::sin(saz) * std::cos(sel), centre[1] + far * std::sin(sel),
                 centre[2] + far * std::cos(saz) * std::cos(sel)};
  s += "light_source {\n  " + vec(sun) + "\n  color rgb " +
       (p.scene_light ? vec(p.sun_color)
        : stormy      ? std::string("<0.55, 0.58, 0.70>")
                      : std::string("<1.25, 1.2, 1.1>")) +
       "\n  parallel point_at " + vec(centre) + "\n}\n";
  if (p.scene_light)  // the scene's own sky lights the shadows (ambient_light)
    s += "\nbackground { rgb " + vec(p.sky_color) + " }\n\n";
  else  // a dim fill from the sky side so shadows are not black
    s += "light_source { " +
         vec({centre[0] - (sun[0] - centre[0]), centre[1] + far, centre[2] - (sun[2] - centre[2])}) +
         " color rgb " + (stormy ? "<0.10, 0.11, 0.16>" : std::string("<0.18, 0.2, 0.26>")) +
         " parallel point_at " + vec(centre) + " shadowless }\n\n";
  if (p.scene_light)
    ;  // the background above
  else if (stormy)
    s += "sky_sphere { pigment { gradient y color_map { [0 rgb <0.30, 0.31, 0.38>] [0.25 rgb <0.12, 0.13, "
         "0.20>] [1 rgb <0.04, 0.05, 0.10>] } } }\n\n";
  else
    s += "sky_sphere { pigment { gradient y color_map { [0 rgb <0.80, 0.86, 0.95>] [0.2 rgb <0.45, 0.62, "
         "0.90>] [1 rgb <0.18, 0.34, 0.72>] } } }\n\n";

  if (p.has_sea) s += "plane { y, " + number(water) + " texture { FT_Sea_Tex } }\n\n";

  if (p.terrain && p.tiles) {
    // The tiles' own PNGs, one height_field each, in the set's common range.
    sum.terrain.z_min = p.tiles->height_min * p.vertical_scale;
    sum.terrain.z_max = p.tiles->height_max * p.vertical_scale;
    const double zw = p.has_sea ? water : sum.terrain.z_min - 1;
    s += "// " + std::to_string(p.tiles->tiles.size()) + " tiles edge to edge (fracterra tiles)\n";
    s += "#declare FT_Terrain_Object = " + tiled_terrain_sdl(*p.tiles, p.vertical_scale, folder, water);
    s += "object { FT_Terrain_Object\n  FT_Terrain_Texture(" + number(sum.terrain.z_min) + ", " +
         number(sum.terrain.z_max) + ", " + number(zw) + ")\n}\n\n";
  } else if (p.terrain) {
    const std::string image = p.image_path.empty() ? default_image_path(pov_path) : p.image_path;
    quoted(relative_path(image, folder));  // a path SDL cannot hold is refused before the PNG is written
    sum.terrain = write_heightfield_png(*p.terrain, image, p.world_size_x, p.world_size_y, p.vertical_scale);
    sum.image_path = image;
    const double zw = p.has_sea ? water : sum.terrain.z_min - 1;
    s += "#declare FT_Terrain_Object = ";
    s += heightfield_sdl(relative_path(image, folder), sum.terrain, water);
    if (p.terrain_colors) {
      const std::string colors = colors_image_path(pov_path, p.image_path);
      const std::string ref = relative_path(colors, folder);
      quoted(ref);
      write_colors_png(colors, *p.terrain, p.terrain_colors);
      sum.colors_path = colors;
      s += "object { FT_Terrain_Object\n" + colors_texture_sdl(ref, sum.terrain, p.scene_light) + "}\n\n";
    } else {
      s += "object { FT_Terrain_Object\n  FT_Terrain_Texture(" + number(sum.terrain.z_min) + ", " +
           number(sum.terrain.z_max) + ", " + number(zw) + ")\n}\n\n";
    }
  } else {
    // Polylines alone: a ground to catch their shadows, just below them.
    // Coastlines alone lie on a sea, where their white reads best.
    bool coast = false;
    for (const auto& l : p.lines) coast = coast || l.kind == LineKind::kCoastline;
    s += "plane { y, " + number(lo[1] - 0.02 * extent) + " texture { " +
         (coast ? "FT_Sea_Tex" : "FT_Ground_Tex") + " } }\n\n";
  }

  for (size_t i = 0; i < p.lines.size(); ++i) {
    const SceneLines& l = p.lines[i];
    SweepOptions o = p.sweep;
    o.default_radius = l.radius > 0 ? l.radius : automatic_line_radius(l, cam, extent, p.image_width);
    o.radius_scale = l.radius_scale;
    PolylineSet sized;
    const PolylineSet& set = l.radii_in_world_units ? *l.set : (sized = tapered(*l.set, o.default_radius));
    if (l.kind == LineKind::kCoastline && p.has_sea) o.use_z_override = true, o.z_override = water;
    const char* tex = l.kind == LineKind::kLightning   ? "FT_Lightning_Tex"
                      : l.kind == LineKind::kCoastline ? "FT_Coast_Tex"
                                                       : "FT_Line_Tex";
    const std::string mods = std::string("  texture { ") + tex + " }\n" +
                             (l.kind == LineKind::kLightning ? "  no_shadow\n" : "");
    s += "// polyline set " + std::to_string(i + 1) + ": " + kind_name(l.kind) + ", " +
         std::to_string(l.set->line_count()) + " lines, " + std::to_string(l.set->vertex_count()) +
         " vertices, radius " + number(o.default_radius * o.radius_scale) +
         (l.radii_in_world_units ? " where a vertex has none" : " (the file's radii as taper)") + "\n";
    s += sweeps_sdl(set, o, mods);
    if (l.kind == LineKind::kLightning) {
      // A faint wide tube around the bolt reads as its glow. A `merge` would
      // hide the faint overlap of the pieces' end spheres but renders 3x
      // slower; at 85% transmit the overlap is barely visible.
      SweepOptions g = o;
      g.radius_scale = 4 * o.radius_scale;
      const std::string glow = sweeps_sdl(set, g, "  texture { FT_Lightning_Glow_Tex }\n  no_shadow\n");
      s += glow;
    }
    if (l.kind == LineKind::kLightning && !l.set->points.empty()) {
      // The bolt lights what is near its foot (its lowest vertex).
      Vec3 foot = to_pov(l.set->points[0]);
      for (const Vec3& w : l.set->points)
        if (w[2] < foot[1]) foot = to_pov(w);
      foot[1] += 0.02 * extent;
      s += "light_source { " + vec(foot) + " color rgb <0.9, 0.95, 1.3>*2 fade_distance " +
           number(0.08 * extent) + " fade_power 2 shadowless }\n";
    }
    s += "\n";
  }

  if (p.rivers && p.rivers->vertex_count() > 0) {
    // Flattened ribbons: the sweep is written FT_River_Flat times as high
    // and squashed back, so its cross-section is a flat ellipse in the bed.
    SceneLines l{p.rivers, LineKind::kGeneric};
    const double floor = automatic_line_radius(l, cam, extent, p.image_width);
    const double flat = 0.3;
    PolylineSet ribbon = *p.rivers;
    for (Vec3& q : ribbon.points) q[2] /= flat;
    for (double& r : ribbon.radii) r = std::max(r, floor);
    SweepOptions o = p.sweep;
    o.default_radius = floor;
    s += "// rivers: " + std::to_string(p.rivers->line_count()) + " segments, radius half the width, at least " +
         number(floor) + "\n";
    s += sweeps_sdl(ribbon, o, "  scale <1, " + number(flat) + ", 1>\n  texture { FT_Water_Tex }\n");
    s += "\n";
  }
  for (size_t k = 0; k < p.lakes.size(); ++k) {
    const SceneLake& l = p.lakes[k];
    size_t n = 0;
    for (const auto& ring : l.rings) n += ring.size();
    if (n == 0) continue;
    s += "// lake " + std::to_string(k) + "\n#declare FT_Lake_Points = array[" + std::to_string(n) + "] {";
    size_t i = 0;
    for (const auto& ring : l.rings)
      for (const Vec3& q : ring) {
        s += i % 4 == 0 ? "\n  " : " ";
        s += "<" + number(q[0]) + ", " + number(q[1]) + ">";
        if (++i < n) s += ",";
      }
    s += "\n}\nFT_Lake(FT_Lake_Points, " + number(l.level) + ", " + number(0.002 * extent) + ")\n";
  }
  out.write(s);
  out.commit();
  return sum;
}

void set_scene_terrain(SceneParams& p, const Heightfield& hf, double world_size_x, double vertical_scale,
                       double sea_fraction) {
  check_positive("terrain world_size_x", world_size_x);
  if (!(vertical_scale >= 0) || !std::isfinite(vertical_scale))
    invalid("vertical_scale must be finite and >= 0 (0 = automatic), got " + format_number(vertical_scale));
  if (!std::isnan(sea_fraction)) check_range("sea_fraction", sea_fraction, 0, 0.999);
  validate_terrain(hf, 1, 1, 1);
  const HeightStats st = hf.stats();
  if (!std::isfinite(st.min) || !std::isfinite(st.max)) invalid("the terrain holds NaN or infinite samples");
  p.terrain = &hf;
  p.world_size_x = world_size_x;
  p.world_size_y = world_size_x * double(hf.height() - 1) / double(hf.width() - 1);
  p.vertical_scale = vertical_scale > 0 ? vertical_scale
                     : st.max > st.min  ? 0.2 * world_size_x / (st.max - st.min)
                                        : 1.0;
  p.has_sea = !std::isnan(sea_fraction);
  if (p.has_sea) {
    std::vector<float> z(hf.data(), hf.data() + hf.size());
    const size_t k = std::min(z.size() - 1, size_t(sea_fraction * double(z.size())));
    std::nth_element(z.begin(), z.begin() + std::ptrdiff_t(k), z.end());
    // Exactly at a sample the sea would cut that sample's flat neighbourhood
    // in stripes: sit a hair above it.
    p.sea_level = (double(z[k]) + 1e-4 * (st.max - st.min)) * p.vertical_scale;
  }
}

SceneSummary write_terrain_scene(const Heightfield& hf, const std::string& pov_path) {
  SceneParams p;
  // A terrain that records its world size is placed in those units with its
  // heights unscaled (they share the unit, as in Blender); one that does not
  // is 1 wide with a relief of 20% of that.
  if (hf.world_size() > 0) set_scene_terrain(p, hf, hf.world_size(), 1.0);
  else set_scene_terrain(p, hf);
  p.title = "terrain " + std::to_string(hf.width()) + " x " + std::to_string(hf.height());
  // Coloured by the built-in splat rules, as `fracterra splat --color` and
  // the Blender material colour it.
  const auto layers = splat::default_layers();
  const std::vector<float> colors =
      splat::splat_colors_linear({&hf, nullptr, nullptr}, layers.data(), int32_t(layers.size()));
  p.terrain_colors = colors.data();
  return write_scene(p, pov_path);
}

SceneSummary write_polyline_scene(const SceneLines& lines, const std::string& pov_path, const CameraOptions& camera,
                                  int32_t image_width) {
  SceneParams p;
  p.lines.push_back(lines);
  p.camera = camera;
  p.image_width = image_width;
  p.title = std::string(kind_name(lines.kind)) + " polylines";
  return write_scene(p, pov_path);
}

}  // namespace ft::pov
