"""Reading objects back: is an object a fracterra terrain (or measurable at
all), a terrain's grid size, and a library heightfield of its current vertex
heights."""

import array
import zlib

import numpy as np

from ... import core
from ...core import params
from ...core.params import grid_shape
from .curve import spline_nodes
from ..common.reporting import SettingsError


def is_terrain(obj):
    return obj is not None and obj.type == "MESH" and obj.fracterra_terrain.is_terrain


def is_polyline(obj):
    """Made by Add > Curve > Fractal Polyline (a curve, or a point mesh for IFS)."""
    return obj is not None and obj.type in {"CURVE", "MESH"} and obj.fracterra_polyline.is_polyline


def is_measurable(obj):
    """Object > Measure works on terrains (H, D) and curves (eta, chi, gamma, D)."""
    return obj is not None and (is_terrain(obj) or obj.type == "CURVE")


def terrain_grid_size(obj):
    """(nx, ny) of a fracterra terrain object whose mesh is still its grid."""
    nx, ny = grid_shape(params.values_of(obj.fracterra_terrain))
    if len(obj.data.vertices) != nx * ny:
        raise SettingsError(f"'{obj.name}' has {len(obj.data.vertices)} vertices, not its {nx} x {ny} grid "
                            "(edited?); regenerate it first")
    return nx, ny


def heightfield_of(obj):
    """A core.Heightfield of a terrain object's current vertex heights (caller closes)."""
    nx, ny = terrain_grid_size(obj)
    co = array.array("f", [0.0]) * (3 * nx * ny)
    obj.data.vertices.foreach_get("co", co)
    return core.Heightfield.from_values(nx, ny, co[2::3])


def geometry_fingerprint(obj):
    """A cheap digest (CRC-32 of every coordinate) of a mesh's vertices or a
    curve's points: the measures it was taken of are stale once it differs."""
    if obj.type == "MESH":
        co = np.empty(3 * len(obj.data.vertices), dtype=np.float32)
        obj.data.vertices.foreach_get("co", co)
        parts = [co]
    else:
        parts = [spline_nodes(spline) for spline in obj.data.splines]
    crc = 0
    for part in parts:
        crc = zlib.crc32(np.ascontiguousarray(part).tobytes(), crc)
    return f"{obj.type}:{sum(len(p) for p in parts)}:{crc:08x}"


def sea_height(settings, lowest):
    """The height of a terrain's flat sea (None without one): its Sea Level, or
    for a sea given as a fraction the terrain's lowest height, where the
    library flattened it (`lowest`: the minimum of its heights)."""
    if settings.sea == "HEIGHT":
        return settings.sea_level
    if settings.sea == "FRACTION":
        return lowest
    return None
