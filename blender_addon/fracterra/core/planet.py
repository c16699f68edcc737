# SPDX-License-Identifier: GPL-3.0-or-later
"""Fractal planets through the C ABI (fracterra/planet.h): the closed
cube-sphere mesh as flat arrays ready for Blender's foreach_set, and the
sea's height. No bpy here."""

import array
from ctypes import byref, c_double, c_float, c_int32, c_int64

from . import params as params_mod
from .binding import library
from .errors import TooLargeError
from .mesh_limits import cube_sphere_too_large
from .terrain import _ProgressBridge, as_pointer, float_array


def planet_struct(values=None, threads=0, **overrides):
    """An ft_planet_params initialised by the library, then filled from settings
    (params.PLANET_PARAMS' names)."""
    lib = library()
    p = lib.planet_params_type()
    lib.check(lib.ft_planet_params_init(byref(p)))
    params_mod.fill_struct(p, {**(values or {}), **overrides}, params_mod.PLANET_PARAMS)
    p.threads = threads
    return p


def mesh_counts(level):
    """(vertices, quads) of the cube-sphere of `level`: 6 4^level + 2 and 6 4^level."""
    lib = library()
    v, f = c_int64(), c_int64()
    lib.check(lib.ft_planet_mesh_counts(level, byref(v), byref(f)))
    return v.value, f.value


class PlanetMesh:
    """co: 3 floats per vertex (metres, radius + vertical_scale x height);
    loop_vertices: 4 per quad (counter-clockwise from outside); heights: 1 per
    vertex (metres above the radius, before the scale); level, vertex_count,
    face_count."""

    def __init__(self, level):
        self.level = level
        self.vertex_count, self.face_count = mesh_counts(level)
        self.co = self.loop_vertices = self.heights = None


def planet_mesh(values, level, vertical_scale, threads=0, progress=None, topology=True):
    """The closed cube-sphere of `level` for settings `values` (raises
    TooLargeError when Blender could not hold it; the library refuses a level
    past its memory cap). `topology`: False skips the quads (an in-place rewrite)."""
    reason = cube_sphere_too_large(level)
    if reason:
        raise TooLargeError(f"Refused before generating: {reason}")
    lib = library()
    p = planet_struct(values, threads)
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    m = PlanetMesh(level)
    m.co = float_array(3 * m.vertex_count)
    m.heights = float_array(m.vertex_count)
    # Unsigned, as the grid's indices: foreach_set then copies with memcpy (core/terrain.index_array).
    m.loop_vertices = array.array("I", [0]) * (4 * m.face_count) if topology else None
    status = lib.ft_planet_mesh(byref(p), level, vertical_scale, as_pointer(m.co, c_float), len(m.co),
                                as_pointer(m.loop_vertices, c_int32) if topology else None,
                                len(m.loop_vertices) if topology else 0, as_pointer(m.heights, c_float),
                                len(m.heights))
    bridge.reraise()
    lib.check(status)
    return m


def sea_height(values):
    """The sea's height in metres above the radius, or None without a sea."""
    lib = library()
    out = c_double()
    lib.check(lib.ft_planet_sea_height(byref(planet_struct(values)), byref(out)))
    return None if out.value != out.value else out.value
