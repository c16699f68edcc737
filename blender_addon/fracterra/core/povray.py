"""POV-Ray scenes through the library's writer (fracterra/povray.h)."""

import os
from ctypes import POINTER, byref, c_float, c_void_p, cast

from .binding import PovSceneLines, library
from .errors import InvalidArgumentError

LINE_KINDS = {"LINE": 0, "LIGHTNING": 1, "COASTLINE": 2}


def write_scene(path, terrain=None, world_size_x=1.0, world_size_y=1.0, vertical_scale=1.0, sea_level=None,
                line_sets=(), camera=None, sun=None, colors=None, light=None):
    """Writes a complete POV-Ray scene to `path` (and `<name>.terrain.png` beside it).

    terrain: a core.Heightfield or None; it spans x 0..world_size_x, y 0..world_size_y.
    line_sets: (Polylines, kind 'LINE'|'LIGHTNING'|'COASTLINE', radius) in the same frame.
    camera: {'azimuth', 'elevation', 'fov', 'aspect'} in degrees (the writer frames the content
    from there), or {'location', 'direction', 'right', 'up'}: a given perspective camera in the
    same frame (ft_pov_scene_params.camera_given); None: the writer's defaults.
    sun: {'azimuth', 'elevation'} in degrees.
    colors: linear RGB per terrain sample, a float32 buffer (numpy array or array('f')) of
    3 * width * height values, painted on the terrain (`<name>.colors.png`); None: fracterra's
    materials by altitude and slope.
    light: {'sky': (r, g, b), 'sun': (r, g, b)} linear RGB (the sun's times its strength): the
    scene's background, ambient light and sun instead of fracterra's.
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
    for entry, (lines, kind, radius) in zip(entries, line_sets):
        entry.lines, entry.kind, entry.radius = lines.handle, LINE_KINDS[kind], radius
    # `lines` is described as an opaque pointer: the array stays alive in `entries`.
    p.lines, p.line_set_count = cast(entries, c_void_p), len(line_sets)
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
    if sun:
        p.sun_azimuth_deg, p.sun_elevation_deg = sun["azimuth"], sun["elevation"]
    lib.check(lib.ft_pov_write_scene(byref(p), os.fsencode(path)))


def render(pov_path, png_path, width=640, height=480, antialias=0.3):
    """Renders `pov_path` with povray into `png_path` (written atomically)."""
    lib = library()
    lib.check(lib.ft_pov_render(os.fsencode(pov_path), os.fsencode(png_path), width, height, antialias))
