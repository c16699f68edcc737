// SPDX-License-Identifier: GPL-3.0-or-later
// Complete POV-Ray scenes a person can render at once: a terrain as a
// height_field with materials by altitude and slope, a sea at the water
// level, polylines as chunked sphere_sweeps (lightning glowing, coastlines
// as thin lines on the sea), a sun, a sky and a camera framed on it all.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/heightfield.hpp"
#include "core/mesh.hpp"
#include "core/polyline_set.hpp"
#include "povray/camera.hpp"
#include "povray/heightfield_export.hpp"
#include "povray/sphere_sweep_export.hpp"
#include "povray/tiled_terrain.hpp"

namespace ft::pov {

enum class LineKind : int32_t { kGeneric = 0, kLightning = 1, kCoastline = 2 };

// A surface as another program shades it (Blender's Principled BSDF or
// Emission shader), linear RGB; written by material_sdl (scene_materials.hpp).
struct SceneMaterial {
  Vec3 color{0.8, 0.8, 0.8};  // base colour, 0..1
  Vec3 emission{0, 0, 0};     // emitted radiance: colour times strength, >= 0
  double roughness = 0.5;     // 0..1: the highlight's width
  double specular = 0.5;      // 0..1: Principled's specular, reflectance at normal incidence 0.08 x specular
  // Water: ft_water.inc's material in this colour, reflecting the sky and the
  // land with Fresnel at the index the specular gives.
  bool water = false;
};

// A light of another program (Blender's), in its physical units, world axes;
// written by light_sdl (scene_materials.hpp) by the rules of docs/povray.md.
enum class LightKind : int32_t { kSun = 0, kPoint = 1, kSpot = 2, kArea = 3 };
struct SceneLight {
  LightKind kind = LightKind::kSun;
  Vec3 color{1, 1, 1};        // linear RGB
  double power = 1;           // W (point, spot; area: its emitted flux); W/m^2 on a surface facing it (sun)
  Vec3 location{};            // point, spot, area
  Vec3 direction{0, 0, -1};   // where it shines (sun, spot, area)
  double spot_size_deg = 45;  // spot: the cone's full angle, 1..180
  double spot_blend = 0.15;   // spot: share of the cone's cosine range that fades, 0..1
  double spot_cos_power = 1;  // spot: the extra cos^k falloff from the axis inside the cone, 0..100
  Vec3 area_u{1, 0, 0}, area_v{0, 1, 0};  // area: its sides (an ellipse's diameters)
  bool area_ellipse = false;
  bool shadows = true;
};

// A mesh drawn in a material (water surfaces, other objects), world axes.
struct SceneMesh {
  const Mesh* mesh = nullptr;  // not owned
  SceneMaterial material;
  bool smooth = false;         // vertex normals (smooth shading); false: flat faces
};

struct SceneLines {
  const PolylineSet* set = nullptr;  // world units, not owned
  LineKind kind = LineKind::kGeneric;
  // Radius of the tube in world units; 0 = automatic: never under 0.75 pixel
  // at the lines' distance (for an image SceneParams::image_width wide), else
  // a tenth of their median segment, capped by their kind's style (0.35%,
  // 0.12% or 0.3% of the scene for lightning, coastlines, lines), so the
  // tube never hides the fractal detail the image can show.
  double radius = 0;
  // The vertex radii of the file: world units where > 0, `radius` where 0
  // (true; the C ABI's rule), or only the taper (false): each vertex gets
  // `radius` times its radius over the set's largest, so branches keep their
  // relative thickness while the size follows the picture (the CLI's default).
  bool radii_in_world_units = true;
  double radius_scale = 1;  // multiplies every radius; > 0
  // Another program's material instead of the kind's (no glow, no light at
  // a lightning's foot: the other program shows none).
  std::optional<SceneMaterial> material = std::nullopt;
};

// A lake: its water surface's height and its shoreline rings (world units,
// as the scene places the terrain; the outer ring first, islands after).
struct SceneLake {
  double level = 0;
  std::vector<std::vector<Vec3>> rings;
};

struct SceneParams {
  const Heightfield* terrain = nullptr;  // may be null (a polyline scene)
  double world_size_x = 1, world_size_y = 1, vertical_scale = 1;
  bool has_sea = false;
  double sea_level = 0;                // world z of the sea
  std::vector<SceneLines> lines;
  // camera.elevation_deg 0 = auto: auto_camera_elevation() of this scene.
  CameraOptions camera;
  // Another program's camera (world axes), used as given instead of the
  // framing above when camera_given.
  bool camera_given = false;
  CameraPose camera_pose;
  double sun_azimuth_deg = 235, sun_elevation_deg = 35;
  // Linear RGB per terrain sample (3 floats each, the terrain's rows), not
  // owned: painted on the terrain (a PNG beside its heights, "x.pov" ->
  // "x.colors.png") instead of the materials by altitude and slope.
  const float* terrain_colors = nullptr;
  // Another program's light: the background and an even ambient light of
  // sky_color, a sun of sun_color (linear RGB times strength), no fill.
  bool scene_light = false;
  Vec3 sky_color{0, 0, 0}, sun_color{1, 1, 1};
  // With scene_light: these lights instead of the sun of sun_color.
  std::vector<SceneLight> lights;
  // The terrain PNG; "" = beside the scene, named after it ("x.pov" -> "x.terrain.png").
  std::string image_path;
  std::string title;                     // written as a comment
  int32_t image_width = 800;             // pixels the automatic line radius is sized for, 16..16384
  // How every line set is swept: spline, segments per sweep, tolerance (the
  // radii come from each SceneLines).
  SweepOptions sweep;
  // A tile set instead of one terrain PNG: `terrain` is then a coarse
  // preview of the whole (for framing and the sea level) and the scene draws
  // these tiles' height_fields edge to edge (tiled_terrain.hpp).
  const TiledTerrain* tiles = nullptr;
  // Rivers (fracterra rivers): vertices on the water surface, radius = half
  // the width, world units as the scene places the terrain (heights scaled
  // by vertical_scale). Drawn as flattened water ribbons (ft_water.inc),
  // never thinner than 0.75 pixel. Not owned; may be null.
  const PolylineSet* rivers = nullptr;
  std::vector<SceneLake> lakes;  // water prisms at their levels (ft_water.inc's FT_Lake)
  // The rivers' and lakes' (and water meshes') colour and gloss; unset:
  // ft_water.inc's own water.
  std::optional<SceneMaterial> water_material;
  std::vector<SceneMesh> meshes;  // each in its material
};

struct SceneSummary {
  Camera camera;
  TerrainPlacement terrain;              // width 0 without terrain
  Vec3 lo{}, hi{};                       // content box, POV axes
  std::string image_path;
  std::string colors_path;               // the terrain colours' PNG, "" without
};

void validate_scene_params(const SceneParams& p);
// Writes the PNG and the scene, each atomically; the scene's folder is
// checked first, so an unwritable destination fails before anything is
// written. Throws ft::Error.
SceneSummary write_scene(const SceneParams& p, const std::string& pov_path);

// Puts a terrain into `p`: world_size_x > 0 (world_size_y follows the grid's aspect),
// vertical_scale 0 = automatic (relief = 20% of world_size_x), sea_fraction in
// [0, 1) puts the sea at that quantile of the heights (NaN: no sea).
void set_scene_terrain(SceneParams& p, const Heightfield& hf, double world_size_x = 1, double vertical_scale = 0,
                       double sea_fraction = 0.3);
// `fracterra terrain ... --pov`: the terrain alone, in its recorded world size
// with heights unscaled (or, without one, with the defaults above), coloured
// by the built-in splat rules (splat/splat_map.hpp).
SceneSummary write_terrain_scene(const Heightfield& hf, const std::string& pov_path);

// The automatic camera elevations (ft_pov_scene_params.camera_elevation_deg
// 0): a terrain is seen from low, polylines alone from high above, and
// lightning, which is vertical, nearly from the side. The table's doc and
// `scene --help` state these numbers; a test holds them together.
constexpr double kTerrainElevationDeg = 22, kLinesElevationDeg = 70, kLightningElevationDeg = 12;
// The elevation auto picks for `p`: kTerrainElevationDeg with a terrain (or
// tiles), else kLightningElevationDeg when every line set is lightning, else
// kLinesElevationDeg.
double auto_camera_elevation(const SceneParams& p);

// Camera defaults for a polyline alone: what auto picks for its kind.
inline CameraOptions polyline_camera(LineKind kind = LineKind::kGeneric) {
  CameraOptions c;
  c.elevation_deg = kind == LineKind::kLightning ? kLightningElevationDeg : kLinesElevationDeg;
  return c;
}

// `fracterra polyline ... --pov`: one polyline set alone, framed, over a
// plain ground, as a lightning, coastline or generic line.
SceneSummary write_polyline_scene(const SceneLines& lines, const std::string& pov_path, const CameraOptions& camera,
                                  int32_t image_width = 800);
// The same with the automatic radius (vertex radii as world units) and the
// camera defaults of its kind.
inline SceneSummary write_polyline_scene(const PolylineSet& set, const std::string& pov_path,
                                         LineKind kind = LineKind::kGeneric) {
  return write_polyline_scene(SceneLines{&set, kind}, pov_path, polyline_camera(kind));
}

// The automatic radius of `lines` (see SceneLines::radius) in a scene whose
// content spans `extent`, seen by `camera` in an image `image_width` wide.
double automatic_line_radius(const SceneLines& lines, const Camera& camera, double extent, int32_t image_width);

// The include files of povray_macros/ this writer embeds in every scene so
// a scene needs nothing beside its PNG (generated from the .inc at build).
extern const char* const kFtTerrainInc;
extern const char* const kFtSceneMaterialsInc;
extern const char* const kFtWaterInc;

}  // namespace ft::pov
