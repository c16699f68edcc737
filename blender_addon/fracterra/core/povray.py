"""POV-Ray scenes through the library's writer (fracterra/povray.h)."""

import os
from ctypes import byref, c_void_p, cast

from .binding import PovSceneLines, library

LINE_KINDS = {"LINE": 0, "LIGHTNING": 1, "COASTLINE": 2}


def write_scene(path, terrain=None, world_size_x=1.0, world_size_y=1.0, vertical_scale=1.0, sea_level=None,
                line_sets=(), camera=None, sun=None):
    """Writes a complete POV-Ray scene to `path` (and `<name>.terrain.png` beside it).

    terrain: a core.Heightfield or None; it spans x 0..world_size_x, y 0..world_size_y.
    line_sets: (Polylines, kind 'LINE'|'LIGHTNING'|'COASTLINE', radius) in the same frame.
    camera: {'azimuth', 'elevation', 'fov', 'aspect'} in degrees (None: the writer frames it).
    sun: {'azimuth', 'elevation'} in degrees.
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
    if camera:
        p.camera_azimuth_deg = camera["azimuth"]
        p.camera_elevation_deg = camera["elevation"]
        p.camera_fov_deg = camera.get("fov", p.camera_fov_deg)
        p.camera_aspect = camera.get("aspect", p.camera_aspect)
    if sun:
        p.sun_azimuth_deg, p.sun_elevation_deg = sun["azimuth"], sun["elevation"]
    lib.check(lib.ft_pov_write_scene(byref(p), os.fsencode(path)))


def render(pov_path, png_path, width=640, height=480, antialias=0.3):
    """Renders `pov_path` with povray into `png_path` (written atomically)."""
    lib = library()
    lib.check(lib.ft_pov_render(os.fsencode(pov_path), os.fsencode(png_path), width, height, antialias))
