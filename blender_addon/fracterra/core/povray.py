# SPDX-License-Identifier: GPL-3.0-or-later
"""POV-Ray scenes through the library's writer (fracterra/povray.h)."""

import os
from ctypes import POINTER, byref, c_float, c_void_p, cast, pointer

from .binding import PovLight, PovMaterial, PovSceneLines, PovSceneMesh, library
from .errors import InvalidArgumentError

LINE_KINDS = {"LINE": 0, "LIGHTNING": 1, "COASTLINE": 2}
LIGHT_KINDS = {"SUN": 0, "POINT": 1, "SPOT": 2, "AREA": 3}


def _fill_material(out, m):
    """A PovMaterial from {'color', 'emission', 'roughness', 'specular', 'water'} (linear RGB)."""
    out.color[:] = tuple(m.get("color", (0.8, 0.8, 0.8)))
    out.emission[:] = tuple(m.get("emission", (0.0, 0.0, 0.0)))
    out.roughness = m.get("roughness", 0.5)
    out.specular = m.get("specular", 0.5)
    out.water = int(bool(m.get("water", False)))
    return out


def _fill_light(out, light):
    """A PovLight from a light dict (see write_scene)."""
    if light["kind"] not in LIGHT_KINDS:
        raise InvalidArgumentError(f"light kind must be one of {', '.join(LIGHT_KINDS)}, got {light['kind']!r}")
    out.kind = LIGHT_KINDS[light["kind"]]
    out.color[:] = tuple(light.get("color", (1.0, 1.0, 1.0)))
    out.power = light["power"]
    out.location[:] = tuple(light.get("location", (0.0, 0.0, 0.0)))
    out.direction[:] = tuple(light.get("direction", (0.0, 0.0, -1.0)))
    out.spot_size_deg = light.get("spot_size_deg", 45.0)
    out.spot_blend = light.get("spot_blend", 0.15)
    out.spot_cos_power = light.get("spot_cos_power", 1.0)
    out.area_u[:] = tuple(light.get("area_u", (1.0, 0.0, 0.0)))
    out.area_v[:] = tuple(light.get("area_v", (0.0, 1.0, 0.0)))
    out.area_ellipse = int(bool(light.get("area_ellipse", False)))
    out.shadows = int(bool(light.get("shadows", True)))
    return out


def write_scene(path, terrain=None, world_size_x=1.0, world_size_y=1.0, vertical_scale=1.0, sea_level=None,
                line_sets=(), camera=None, sun=None, colors=None, light=None, lights=(), rivers=None,
                water_material=None, meshes=()):
    """Writes a complete POV-Ray scene to `path` (and `<name>.terrain.png` beside it).

    terrain: a core.Heightfield or None; it spans x 0..world_size_x, y 0..world_size_y.
    line_sets: (Polylines, kind 'LINE'|'LIGHTNING'|'COASTLINE', radius[, material]) in the same
    frame; a material (a dict as below, or None) replaces the kind's look.
    camera: {'azimuth', 'elevation', 'fov', 'aspect'} in degrees (the writer frames the content
    from there), or {'location', 'direction', 'right', 'up'}: a given perspective camera in the
    same frame (ft_pov_scene_params.camera_given); None: the writer's defaults.
    sun: {'azimuth', 'elevation'} in degrees.
    colors: linear RGB per terrain sample, a float32 buffer (numpy array or array('f')) of
    3 * width * height values, painted on the terrain (`<name>.colors.png`); None: fracterra's
    materials by altitude and slope.
    light: {'sky': (r, g, b), 'sun': (r, g, b)} linear RGB (the sun's times its strength): the
    scene's background, ambient light and sun instead of fracterra's.
    lights: with `light`, these lights instead of its sun: dicts of ft_pov_light's fields
    ('kind' 'SUN'|'POINT'|'SPOT'|'AREA', 'color', 'power' in Blender's units, 'location',
    'direction', 'spot_size_deg', 'spot_blend', 'spot_cos_power', 'area_u', 'area_v',
    'area_ellipse', 'shadows') in the same frame.
    rivers: a Polylines of rivers (radius half the width), drawn as water ribbons.
    water_material, and each material: {'color', 'emission', 'roughness', 'specular', 'water'}.
    meshes: (core.Mesh, material, smooth) in the same frame.
    """
    lib = library()
    p = lib.pov_scene_params_type()
    lib.check(lib.ft_pov_scene_params_init(byref(p)))
    if terrain is not None:
        p.terrain = terrain.handle
        p.world_size_x, p.world_size_y, p.vertical_scale = world_size_x, world_size_y, vertical_scale
    if sea_level is not None:
        p.has_sea, p.sea_level = 1, sea_level
    entries = (PovSceneLines * max(1, len(line_sets)))()
    line_materials = (PovMaterial * max(1, len(line_sets)))()
    styled = False
    for entry, material, line_set in zip(entries, line_materials, line_sets):
        lines, kind, radius = line_set[:3]
        entry.lines, entry.kind, entry.radius = lines.handle, LINE_KINDS[kind], radius
        if len(line_set) > 3 and line_set[3] is not None:
            _fill_material(material, line_set[3])
            styled = True
    # The arrays are described as opaque pointers: they stay alive in these locals.
    p.lines, p.line_set_count = cast(entries, c_void_p), len(line_sets)
    if styled:
        if not all(len(ls) > 3 and ls[3] is not None for ls in line_sets):
            raise InvalidArgumentError("give every line set a material, or none")
        p.line_materials = cast(line_materials, c_void_p)
    if camera and "location" in camera:
        p.camera_given = 1
        for name in ("location", "direction", "right", "up"):
            getattr(p, "camera_" + name)[:] = tuple(camera[name])
    elif camera:
        p.camera_azimuth_deg = camera["azimuth"]
        p.camera_elevation_deg = camera["elevation"]
        p.camera_fov_deg = camera.get("fov", p.camera_fov_deg)
        p.camera_aspect = camera.get("aspect", p.camera_aspect)
    color_buffer = None
    if colors is not None:
        raw = memoryview(colors).cast("B")
        want = 3 * terrain.width * terrain.height if terrain is not None else 0
        if len(raw) != 4 * want:
            raise InvalidArgumentError(f"terrain colours: {len(raw) // 4} floats given, the terrain needs {want} "
                                       "(3 per sample)")
        color_buffer = (c_float * want).from_buffer_copy(raw)  # alive until the call returns
        p.terrain_colors = cast(color_buffer, POINTER(c_float))
    if light:
        p.has_scene_light = 1
        p.sky_color[:] = tuple(light["sky"])
        p.sun_color[:] = tuple(light["sun"])
    light_array = (PovLight * max(1, len(lights)))()
    for out, given in zip(light_array, lights):
        _fill_light(out, given)
    p.lights, p.light_count = cast(light_array, c_void_p), len(lights)
    if rivers is not None:
        p.rivers = rivers.handle
    water = _fill_material(PovMaterial(), water_material) if water_material else None
    if water is not None:
        p.water_material = cast(pointer(water), c_void_p)
    mesh_array = (PovSceneMesh * max(1, len(meshes)))()
    for out, (mesh, material, smooth) in zip(mesh_array, meshes):
        out.mesh, out.smooth = mesh.handle, int(bool(smooth))
        _fill_material(out.material, material or {})
    p.meshes, p.mesh_count = cast(mesh_array, c_void_p), len(meshes)
    if sun:
        p.sun_azimuth_deg, p.sun_elevation_deg = sun["azimuth"], sun["elevation"]
    lib.check(lib.ft_pov_write_scene(byref(p), os.fsencode(path)))


def render(pov_path, png_path, width=640, height=480, antialias=0.3):
    """Renders `pov_path` with povray into `png_path` (written atomically)."""
    lib = library()
    lib.check(lib.ft_pov_render(os.fsencode(pov_path), os.fsencode(png_path), width, height, antialias))
