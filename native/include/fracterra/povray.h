// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/povray.h
/// POV-Ray export: terrains as `height_field` (16-bit PNG + SDL), polylines
/// as chunked `sphere_sweep` unions, and complete scenes ready to render.
/// Scenes use POV-Ray 3.7 SDL; every file is written atomically (temporary
/// name, then rename), so a failed call leaves no partial file.
/// Axes: fracterra's world (x, y, z up) is POV-Ray <x, z, y>.
#ifndef FRACTERRA_POVRAY_H
#define FRACTERRA_POVRAY_H

#include "core.h"
#include "subdiv.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Kinds of polyline sets in a scene.
enum {
  FT_POV_LINE = 0,       ///< a plain orange tube
  FT_POV_LIGHTNING = 1,  ///< glowing (emissive, casts no shadow) with a light at its foot
  FT_POV_COASTLINE = 2   ///< thin foam-white line laid on the sea (z = water level)
};

/// Sweep splines.
enum { FT_POV_SWEEP_LINEAR = 0, FT_POV_SWEEP_CUBIC = 1 };

/// One polyline set in a scene.
typedef struct ft_pov_scene_lines {
  const ft_polylines* lines;  ///< world units; not owned, must not be NULL
  int32_t kind;               ///< FT_POV_LINE, FT_POV_LIGHTNING or FT_POV_COASTLINE
  double radius;              ///< sweep radius where a vertex has none (radius 0); 0 = by kind and scene size
} ft_pov_scene_lines;

/// Light kinds (ft_pov_light.kind): Blender's.
enum { FT_POV_LIGHT_SUN = 0, FT_POV_LIGHT_POINT = 1, FT_POV_LIGHT_SPOT = 2, FT_POV_LIGHT_AREA = 3 };

/// A light in another program's physical units (Blender's Cycles), world axes (ABI 2.26). The
/// writer converts it so that a white diffuse surface facing it is as bright in POV-Ray as there:
/// a sun's colour is colour * power / pi; point and spot lights fade with the inverse square law
/// (fade_power 2); an area light is a grid of lights with a Lambertian falloff. The formulas and
/// their sources: docs/povray.md, "Lights".
typedef struct ft_pov_light {
  int32_t kind;             ///< FT_POV_LIGHT_SUN, _POINT, _SPOT or _AREA
  double color[3];          ///< linear RGB, 0..1000 each
  double power;             ///< W (point, spot: Blender's Power; area: the flux it emits, which is Blender's
                            ///< Power from 4.0 on and pi / 4 of it before); W/m^2 (sun: its Strength), 0..1e12
  double location[3];       ///< world point (point, spot, area)
  double direction[3];      ///< world direction the light shines in (sun, spot, area: its face's normal); not zero
  double spot_size_deg;     ///< spot: the cone's full angle, 1..180 (Blender's Spot Size)
  double spot_blend;        ///< spot: 0..1, the share of the cone's cosine range that fades (Blender's Blend)
  double spot_cos_power;    ///< spot: an extra cos^k falloff from the axis inside the cone, 0..100
                            ///< (Cycles before Blender 4.0: 1)
  double area_u[3];         ///< area: its side along its local x (an ellipse's diameter), world
  double area_v[3];         ///< area: its side along its local y, world
  int32_t area_ellipse;     ///< area: 1 for a disk or ellipse, 0 for a square or rectangle
  int32_t shadows;          ///< 1: casts shadows; 0: shadowless
} ft_pov_light;

/// A surface as another program shades it (Blender's Principled BSDF or Emission), linear RGB (ABI 2.26).
typedef struct ft_pov_material {
  double color[3];          ///< base colour, 0..1 each
  double emission[3];       ///< emitted radiance (colour * strength), 0..1e6 each
  double roughness;         ///< 0..1: the highlight's width; below 0.3 the surface also mirrors with Fresnel
  double specular;          ///< 0..1: Principled's specular (reflectance 0.08 * specular straight on)
  int32_t water;            ///< 1: water (mirrors with Fresnel whatever its roughness)
} ft_pov_material;

/// A mesh in a scene (ABI 2.26): water surfaces (lakes, the sea) and other objects.
typedef struct ft_pov_scene_mesh {
  const ft_mesh* mesh;      ///< world units; not owned, must not be NULL
  ft_pov_material material; ///< its material; water = 1 wears the scene's water (water_material)
  int32_t smooth;           ///< 1: smooth shading (vertex normals); 0: flat faces
} ft_pov_scene_mesh;

typedef struct ft_pov_scene_params {
  uint32_t struct_size;             ///< sizeof(ft_pov_scene_params)
  const ft_heightfield* terrain;    ///< may be NULL (polylines only); not owned
  double world_size_x;                    ///< terrain extent across columns (world x), > 0; default 1
  double world_size_y;                    ///< across rows (world y), > 0; default 1
  double vertical_scale;            ///< heights = samples * vertical_scale, > 0; default 1
  int32_t has_sea;                ///< 1: a sea plane at sea_level; default 0
  double sea_level;               ///< world z of the sea; default 0
  const ft_pov_scene_lines* lines;  ///< line_set_count entries; may be NULL when the count is 0
  int32_t line_set_count;           ///< 0..1024; default 0
  double camera_azimuth_deg;        ///< from the content to the camera, 0 = +y, 90 = +x; -360..360; default 200
  double camera_elevation_deg;      ///< 1..90, or 0 = auto (default): 22 over a terrain, 70 for
                                    ///< polylines alone, 12 when every line set is lightning
  double camera_fov_deg;            ///< horizontal field of view, 5..150; default 50
  double camera_aspect;             ///< width / height the framing is for, 0.1..10; default 4/3
  double camera_distance_scale;     ///< > 1 backs off from the framed distance, 0.1..100; default 1
  double sun_azimuth_deg;           ///< -360..360; default 235
  double sun_elevation_deg;         ///< 1..90; default 35
  const char* image_path;           ///< terrain PNG; NULL = beside the scene, "x.pov" -> "x.terrain.png"
  double camera_margin;             ///< free border, fraction of the half-frame, 0..0.5; default 0.04 (ABI 2.11)
  double camera_center_v;           ///< image row (0 top .. 1 bottom) of the content's middle, 0.2..0.8;
                                    ///< default 0.55 (above 0.5 leaves more sky) (ABI 2.11)
  /// ABI 2.17: another program's view of the scene (Blender's), so both render it alike.
  int32_t camera_given;             ///< 1: the camera below, as given; 0 (default): framed on the content
                                    ///< from the azimuth, elevation, field of view and aspect above
  double camera_location[3];        ///< world point of the eye (camera_given)
  /// POV-Ray's perspective camera in world axes (camera_given): the ray of image point (u, v)
  /// (0..1 each, u right, v down from the top) runs along direction + (u - 0.5) right + (0.5 - v) up,
  /// so |right| / |direction| = 2 tan(horizontal angle / 2), |right| / |up| is the image aspect and a
  /// lens shift is a direction not perpendicular to them. Render at that aspect.
  double camera_direction[3];
  double camera_right[3];
  double camera_up[3];
  /// Linear RGB of each terrain sample (3 floats per sample, rows as in the heightfield), painted
  /// on the terrain instead of the sand, grass, rock and snow by altitude; NULL (default): those.
  const float* terrain_colors;
  int32_t has_scene_light;          ///< 1: a background and even ambient light of sky_color and a sun
                                    ///< of sun_color, no fill light; 0 (default): fracterra's sky and sun
  double sky_color[3];              ///< linear RGB, 0..1000 each (has_scene_light); default 0
  double sun_color[3];              ///< linear RGB times strength, 0..1000 each (has_scene_light); default 1
  /// ABI 2.26: the rest of another program's scene.
  const ft_pov_light* lights;       ///< light_count lights (has_scene_light) instead of the sun of sun_color
  int32_t light_count;              ///< 0..1024; default 0 (the sun of sun_color)
  const ft_pov_material* line_materials;  ///< NULL, or line_set_count materials, one per line set,
                                          ///< instead of its kind's (no glow, no light at a bolt's foot)
  const ft_polylines* rivers;       ///< rivers as water ribbons (radius = half the width, z = the water
                                    ///< surface), world units; NULL: none
  const ft_pov_material* water_material;  ///< the rivers' and water meshes' material; NULL: ft_water.inc's
  const ft_pov_scene_mesh* meshes;  ///< mesh_count meshes; may be NULL when the count is 0
  int32_t mesh_count;               ///< 0..65536; default 0
} ft_pov_scene_params;

/// Fills `p` with the defaults above (FT_ERR_INVALID_ARGUMENT for NULL).
FT_API ft_status ft_pov_scene_params_init(ft_pov_scene_params* p);

/// Writes a complete scene to `pov_path` (and the terrain PNG when there is a
/// terrain): camera framed on the content, sun, sky, sea, terrain material by
/// altitude and slope, polylines as sweeps. The scene refers to the PNG by a
/// relative, quoted path. FT_ERR_IO if the folder is missing or unwritable.
FT_API ft_status ft_pov_write_scene(const ft_pov_scene_params* p, const char* pov_path);

/// Writes `hf` as the 16-bit grayscale PNG a height_field reads (normalised
/// to 0..65535, real range in tEXt) and, when `inc_path` is not NULL, an
/// include file declaring `name` (a POV-Ray identifier with a capital
/// letter, e.g. "Terrain") as the smooth height_field in real units:
/// columns span x 0..world_size_x, rows z 0..world_size_y, heights y = samples *
/// vertical_scale. `z_min`/`z_max` (may be NULL) receive the height range.
FT_API ft_status ft_pov_write_heightfield(const ft_heightfield* hf, const char* png_path, const char* inc_path,
                                         const char* name, double world_size_x, double world_size_y,
                                         double vertical_scale, double* z_min, double* z_max);

typedef struct ft_pov_sweep_params {
  uint32_t struct_size;        ///< sizeof(ft_pov_sweep_params)
  int32_t spline;              ///< FT_POV_SWEEP_LINEAR (default) or FT_POV_SWEEP_CUBIC
  int64_t segments_per_sweep;  ///< 1..2^30, default 32 (16..64 renders fastest)
  double default_radius;       ///< where a vertex radius is 0, > 0; default 0.01
  double radius_scale;         ///< multiplies every radius, > 0; default 1
  double tolerance;            ///< cubic sweeps' tolerance, > 0; default 1e-3
} ft_pov_sweep_params;

/// Fills `p` with the defaults above (FT_ERR_INVALID_ARGUMENT for NULL).
FT_API ft_status ft_pov_sweep_params_init(ft_pov_sweep_params* p);

/// Writes an include file declaring `name` (identifier as above) as one
/// object, a union of short sphere_sweeps, without texture:
/// `object { name texture { ... } }` in the including scene.
FT_API ft_status ft_pov_write_sweeps(const ft_polylines* lines, const ft_pov_sweep_params* p,
                                     const char* inc_path, const char* name);

/// Runs povray on `pov_path` and writes the PNG `out_png` (atomically):
/// width x height pixels, anti-aliasing threshold `antialias` (0 = off).
/// On failure the message holds POV-Ray's error lines.
FT_API ft_status ft_pov_render(const char* pov_path, const char* out_png, int32_t width, int32_t height,
                               double antialias);

#ifdef __cplusplus
}
#endif
#endif
