// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/pov_params.hpp"

#include <cfloat>

namespace ft::pov {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr uint32_t kAbove = FT_PARAM_FLAG_MIN_EXCLUSIVE;  // > hard_min
constexpr double kInf = DBL_MAX;
constexpr uint32_t kAbi211 = 0x2000B;  // camera_margin, camera_center_v; elevation 0 = auto
constexpr uint32_t kAbi217 = 0x20011;  // a given camera, terrain colours, scene light
constexpr uint32_t kAbi226 = 0x2001A;  // lights, materials, rivers and meshes of another program's scene

#define ROW(field, type) FT_PARAM_ROW(ft_pov_scene_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kSceneRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_pov_scene_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_pov_scene_params), set by ft_pov_scene_params_init", .methods = kAll},
    {ROW(terrain, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_OPAQUE, .element_kind = -1,
     .unit = "", .label = "Terrain", .doc = "The ft_heightfield to show, or NULL (polylines only); not owned",
     .methods = kAll},
    {ROW(world_size_x, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.1, .soft_max = 1000, .unit = "scene units", .label = "Width",
     .doc = "Terrain extent across its columns (world x)", .methods = kAll},
    {ROW(world_size_y, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.1, .soft_max = 1000, .unit = "scene units", .label = "Depth",
     .doc = "Terrain extent across its rows (world y)", .methods = kAll},
    {ROW(vertical_scale, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.01, .soft_max = 100, .unit = "", .label = "Vertical Scale",
     .doc = "World heights are the samples times this", .methods = kAll},
    {ROW(has_sea, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Sea", .doc = "A sea plane at sea_level", .methods = kAll},
    {ROW(sea_level, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = -kInf, .hard_max = kInf,
     .soft_min = -10, .soft_max = 10, .unit = "scene units", .label = "Sea Level",
     .doc = "World z of the sea plane (with has_sea)", .methods = kAll},
    {ROW(lines, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_OPAQUE, .element_kind = -1, .unit = "",
     .label = "Line Sets",
     .doc = "line_set_count ft_pov_scene_lines (polylines, their kind and radius); NULL when the count is 0",
     .methods = kAll},
    {ROW(line_set_count, FT_PARAM_INT32), .flags = kData, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1024, .soft_min = 0, .soft_max = 16, .unit = "", .label = "Line Set Count",
     .doc = "Entries in lines", .methods = kAll},
    {ROW(camera_azimuth_deg, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 200, .hard_min = -360,
     .hard_max = 360, .soft_min = 0, .soft_max = 360, .unit = "degrees", .label = "Camera Azimuth",
     .doc = "Compass direction from the content to the camera: 0 = +y (north), 90 = +x", .methods = kAll},
    // Auto, because one number cannot suit every scene: a terrain is seen from
    // low (22), polylines alone from high above (70), lightning, which is
    // vertical, nearly from the side (12). scene.hpp holds the three values.
    {ROW(camera_elevation_deg, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_ZERO_IS_AUTO, .element_kind = -1,
     .default_value = 0, .hard_min = 1, .hard_max = 90, .soft_min = 5, .soft_max = 90, .unit = "degrees",
     .label = "Camera Elevation",
     .doc = "Camera angle above the horizon, seen from the content; 0: auto, by what the scene holds: 22 with a "
            "terrain, 70 for polylines alone, 12 when every line set is lightning",
     .methods = kAll},
    {ROW(camera_fov_deg, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 50, .hard_min = 5, .hard_max = 150,
     .soft_min = 20, .soft_max = 90, .unit = "degrees", .label = "Field of View",
     .doc = "Horizontal field of view (POV-Ray's camera angle)", .methods = kAll},
    {ROW(camera_aspect, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 4.0 / 3.0, .hard_min = 0.1,
     .hard_max = 10, .soft_min = 0.5, .soft_max = 2.5, .unit = "", .label = "Aspect",
     .doc = "Image width / height the framing is made for", .methods = kAll},
    {ROW(camera_distance_scale, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 1, .hard_min = 0.1,
     .hard_max = 100, .soft_min = 0.5, .soft_max = 4, .unit = "", .label = "Zoom Out",
     .doc = "Camera distance relative to the one that frames the content (> 1 backs off)", .methods = kAll},
    {ROW(sun_azimuth_deg, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 235, .hard_min = -360,
     .hard_max = 360, .soft_min = 0, .soft_max = 360, .unit = "degrees", .label = "Sun Azimuth",
     .doc = "Compass direction of the sun: 0 = +y (north), 90 = +x", .methods = kAll},
    {ROW(sun_elevation_deg, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 35, .hard_min = 1,
     .hard_max = 90, .soft_min = 5, .soft_max = 90, .unit = "degrees", .label = "Sun Elevation",
     .doc = "Sun angle above the horizon", .methods = kAll},
    {ROW(image_path, FT_PARAM_STRING), .flags = kData, .element_kind = -1, .unit = "", .label = "Terrain Image",
     .doc = "Path of the terrain's 16-bit PNG; NULL: beside the scene, \"x.pov\" -> \"x.terrain.png\"",
     .methods = kAll},
    {ROW(camera_margin, FT_PARAM_DOUBLE), .since = kAbi211, .element_kind = -1, .default_value = 0.04,
     .hard_min = 0, .hard_max = 0.5, .soft_min = 0, .soft_max = 0.2, .unit = "", .label = "Margin",
     .doc = "Free border around the framed content, as a fraction of the half-frame", .methods = kAll},
    {ROW(camera_center_v, FT_PARAM_DOUBLE), .since = kAbi211, .element_kind = -1, .default_value = 0.55,
     .hard_min = 0.2, .hard_max = 0.8, .soft_min = 0.4, .soft_max = 0.7, .unit = "", .label = "Vertical Centre",
     .doc = "Image row (0 top .. 1 bottom) where the middle of the framed content lands; above 0.5 leaves more "
            "sky",
     .methods = kAll},
    {ROW(camera_given, FT_PARAM_BOOL), .since = kAbi217, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Given Camera",
     .doc = "Use camera_location, camera_direction, camera_right and camera_up as given (e.g. Blender's scene "
            "camera) instead of framing the content",
     .methods = kAll},
    {ROW(camera_location, FT_PARAM_DOUBLE), .since = kAbi217, .element_kind = -1, .default_value = 0,
     .hard_min = -kInf, .hard_max = kInf, .soft_min = -100, .soft_max = 100, .unit = "scene units",
     .label = "Camera Location", .doc = "World point of the given camera's eye", .methods = kAll},
    {ROW(camera_direction, FT_PARAM_DOUBLE), .since = kAbi217, .element_kind = -1, .default_value = 0,
     .hard_min = -kInf, .hard_max = kInf, .soft_min = -1, .soft_max = 1, .unit = "", .label = "Camera Direction",
     .doc = "The given camera's direction (POV-Ray's perspective camera, world axes): from the eye to the image "
            "centre; with right and up it sets the angle and any lens shift",
     .methods = kAll},
    {ROW(camera_right, FT_PARAM_DOUBLE), .since = kAbi217, .element_kind = -1, .default_value = 0,
     .hard_min = -kInf, .hard_max = kInf, .soft_min = -1, .soft_max = 1, .unit = "", .label = "Camera Right",
     .doc = "The given camera's image width as a world vector to the right (|right| / |direction| = 2 tan(angle "
            "/ 2))",
     .methods = kAll},
    {ROW(camera_up, FT_PARAM_DOUBLE), .since = kAbi217, .element_kind = -1, .default_value = 0,
     .hard_min = -kInf, .hard_max = kInf, .soft_min = -1, .soft_max = 1, .unit = "", .label = "Camera Up",
     .doc = "The given camera's image height as a world vector upwards (|right| / |up| = the image aspect)",
     .methods = kAll},
    {ROW(terrain_colors, FT_PARAM_POINTER), .flags = kData, .since = kAbi217, .element_type = FT_PARAM_FLOAT,
     .element_kind = -1, .unit = "", .label = "Terrain Colours",
     .doc = "Linear RGB of each terrain sample (3 floats per sample, the heightfield's rows), painted on the "
            "terrain; NULL: sand, grass, rock and snow by altitude and slope",
     .methods = kAll},
    {ROW(has_scene_light, FT_PARAM_BOOL), .since = kAbi217, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Scene Light",
     .doc = "A background and even ambient light of sky_color and a sun of sun_color, without fill light "
            "(another program's lighting); 0: fracterra's sky, sun and fill",
     .methods = kAll},
    {ROW(sky_color, FT_PARAM_DOUBLE), .since = kAbi217, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1000, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Sky Colour",
     .doc = "Linear RGB of the background and the ambient light (with has_scene_light)", .methods = kAll},
    {ROW(sun_color, FT_PARAM_DOUBLE), .since = kAbi217, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 1000, .soft_min = 0, .soft_max = 10, .unit = "", .label = "Sun Colour",
     .doc = "Linear RGB of the sun times its strength (with has_scene_light): 1 lights a white surface facing "
            "it to 1",
     .methods = kAll},
    {ROW(lights, FT_PARAM_POINTER), .flags = kData, .since = kAbi226, .element_type = FT_PARAM_OPAQUE,
     .element_kind = -1, .unit = "", .label = "Lights",
     .doc = "light_count ft_pov_light (Blender's lights in its units) instead of the sun of sun_color (with "
            "has_scene_light); NULL when the count is 0",
     .methods = kAll},
    {ROW(light_count, FT_PARAM_INT32), .flags = kData, .since = kAbi226, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = 1024, .soft_min = 0, .soft_max = 16, .unit = "", .label = "Light Count",
     .doc = "Entries in lights", .methods = kAll},
    {ROW(line_materials, FT_PARAM_POINTER), .flags = kData, .since = kAbi226, .element_type = FT_PARAM_OPAQUE,
     .element_kind = -1, .unit = "", .label = "Line Materials",
     .doc = "NULL, or line_set_count ft_pov_material: each line set's material instead of its kind's",
     .methods = kAll},
    {ROW(rivers, FT_PARAM_POINTER), .flags = kData, .since = kAbi226, .element_type = FT_PARAM_OPAQUE,
     .element_kind = -1, .unit = "", .label = "Rivers",
     .doc = "ft_polylines of rivers (vertices on the water surface, radius half the width), drawn as flattened "
            "water ribbons; NULL: none; not owned",
     .methods = kAll},
    {ROW(water_material, FT_PARAM_POINTER), .flags = kData, .since = kAbi226, .element_type = FT_PARAM_OPAQUE,
     .element_kind = -1, .unit = "", .label = "Water Material",
     .doc = "The ft_pov_material of rivers and water meshes; NULL: ft_water.inc's water", .methods = kAll},
    {ROW(meshes, FT_PARAM_POINTER), .flags = kData, .since = kAbi226, .element_type = FT_PARAM_OPAQUE,
     .element_kind = -1, .unit = "", .label = "Meshes",
     .doc = "mesh_count ft_pov_scene_mesh (a mesh, its material, smooth or flat); NULL when the count is 0",
     .methods = kAll},
    {ROW(mesh_count, FT_PARAM_INT32), .flags = kData, .since = kAbi226, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = 65536, .soft_min = 0, .soft_max = 16, .unit = "", .label = "Mesh Count",
     .doc = "Entries in meshes", .methods = kAll},
};
#undef ROW

constexpr ft_param_enum_item kSplines[] = {
    {FT_POV_SWEEP_LINEAR, "LINEAR", "Linear", "linear_spline sweeps: straight segments, as the polyline is"},
    {FT_POV_SWEEP_CUBIC, "CUBIC", "Cubic", "cubic_spline sweeps: smooth through the vertices, slower to trace"},
};

#define ROW(field, type) FT_PARAM_ROW(ft_pov_sweep_params, field, type)
constexpr ft_param_info kSweepRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_pov_sweep_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_pov_sweep_params), set by ft_pov_sweep_params_init", .methods = kAll},
    {ROW(spline, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_POV_SWEEP_LINEAR, .hard_min = 0,
     .hard_max = FT_POV_SWEEP_CUBIC, .soft_min = 0, .soft_max = FT_POV_SWEEP_CUBIC, .unit = "", .label = "Spline",
     .doc = "The sphere_sweep's spline", .methods = kAll, .enum_count = 2, .enum_items = kSplines},
    {ROW(segments_per_sweep, FT_PARAM_INT64), .element_kind = -1, .default_value = 32, .hard_min = 1,
     .hard_max = 1073741824.0, .soft_min = 16, .soft_max = 64, .unit = "segments", .label = "Segments per Sweep",
     .doc = "A polyline is cut into sweeps of this many segments (16..64 traces fastest: each piece gets a tight "
            "bounding box)",
     .methods = kAll},
    {ROW(default_radius, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 0.01,
     .hard_min = 0, .hard_max = kInf, .soft_min = 0.0001, .soft_max = 0.1, .unit = "scene units",
     .label = "Radius", .doc = "Tube radius where a vertex has none (radius 0)", .methods = kAll},
    {ROW(radius_scale, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.1, .soft_max = 10, .unit = "", .label = "Radius Scale",
     .doc = "Multiplies every radius (the taper is kept)", .methods = kAll},
    {ROW(tolerance, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1e-3, .hard_min = 0,
     .hard_max = kInf, .soft_min = 1e-6, .soft_max = 0.01, .unit = "", .label = "Tolerance",
     .doc = "Cubic sweeps' intersection depth tolerance (POV-Ray's sphere_sweep tolerance)", .methods = kAll},
};
#undef ROW
FT_PARAM_TABLE_END

}  // namespace

const ParamTable& scene_param_table() {
  static const ParamTable table{"ft_pov_scene_params", sizeof(ft_pov_scene_params), kSceneRows};
  return table;
}

const ParamTable& sweep_param_table() {
  static const ParamTable table{"ft_pov_sweep_params", sizeof(ft_pov_sweep_params), kSweepRows};
  return table;
}

namespace {

// Each settings row of the tables into the exporter's own types; the tests
// ask unbound_rows() that none is left out.
#define BIND(row, member) FT_PARAM_BIND(SceneParams, row, member)
const ParamBinding<SceneParams> kSceneBindings[] = {
    BIND(world_size_x, world_size_x),
    BIND(world_size_y, world_size_y),
    BIND(vertical_scale, vertical_scale),
    BIND(has_sea, has_sea),
    BIND(sea_level, sea_level),
    BIND(camera_azimuth_deg, camera.azimuth_deg),
    BIND(camera_elevation_deg, camera.elevation_deg),
    BIND(camera_fov_deg, camera.fov_deg),
    BIND(camera_aspect, camera.aspect),
    BIND(camera_distance_scale, camera.distance_scale),
    BIND(sun_azimuth_deg, sun_azimuth_deg),
    BIND(sun_elevation_deg, sun_elevation_deg),
    BIND(camera_margin, camera.margin),
    BIND(camera_center_v, camera.center_v),
    BIND(camera_given, camera_given),
    BIND(camera_location, camera_pose.location),
    BIND(camera_direction, camera_pose.direction),
    BIND(camera_right, camera_pose.right),
    BIND(camera_up, camera_pose.up),
    BIND(has_scene_light, scene_light),
    BIND(sky_color, sky_color),
    BIND(sun_color, sun_color),
};
#undef BIND
#define BIND(row, member) FT_PARAM_BIND(SweepOptions, row, member)
const ParamBinding<SweepOptions> kSweepBindings[] = {
    BIND(spline, spline),
    BIND(segments_per_sweep, segments_per_sweep),
    BIND(default_radius, default_radius),
    BIND(radius_scale, radius_scale),
    BIND(tolerance, tolerance),
};
#undef BIND

}  // namespace

std::span<const ParamBinding<SceneParams>> scene_bindings() { return kSceneBindings; }
std::span<const ParamBinding<SweepOptions>> sweep_bindings() { return kSweepBindings; }

void apply_scene_settings(const ft_pov_scene_params& c, SceneParams& s) {
  // The camera's ranges are checked here only: frame_points trusts them.
  apply_bindings(scene_param_table(), &c, scene_bindings(), s);
}

SweepOptions sweep_options(const ft_pov_sweep_params& c) {
  SweepOptions o;
  apply_bindings(sweep_param_table(), &c, sweep_bindings(), o);
  return o;
}

}  // namespace ft::pov
