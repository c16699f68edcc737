# SPDX-License-Identifier: GPL-3.0-or-later
"""A terrain's coastline: where the level is (a height, a quantile, or the
terrain's sea), the trace (bpy-free, so a job's worker runs it) and the curve.

A coastline object keeps what it was asked for (COAST_SETTINGS, JSON on the
object), so a terrain that re-generates retraces it in the same job
(terrain.py) from the new heights: it never stays at the old surface.
"""

import json

import bpy
import numpy as np

from ... import core
from .curve import LineArrays, fill_curve_steps, new_curve
from .objects import sea_height_of
from ..common.reporting import SettingsError

KIND = "COASTLINE"
COAST_SETTINGS = "fracterra_coast"


def land_quantile(z, sea, q):
    """The height with the fraction `q` of the land (heights above the flat sea
    at `sea`) below it. The flat sea is left out: when it covers more than half
    the map, a quantile of all heights would fall on it and find no coast."""
    land = np.sort(z[z > sea])
    if land.size == 0:
        raise SettingsError(f"no land above the sea at {sea:g}: the whole terrain is sea; lower its Sea Level")
    return float(land[min(land.size - 1, int(q * land.size))])


def level_of(hf, request):
    """(level, by_quantile) for library.coastline on heightfield `hf`.
    `request`: {"use_quantile", "quantile", "level", "sea", "sea_level"}, the
    operator's settings and the terrain's sea; with "level_from_sea" the level
    is the sea's (a re-generated sea moves it)."""
    z = np.frombuffer(hf.to_array(), dtype=np.float32)
    lowest, highest = float(z.min()), float(z.max())
    sea = sea_height_of(request["sea"], request["sea_level"], lowest)
    level = request["quantile"] if request["use_quantile"] else request["level"]
    if request.get("level_from_sea") and sea is not None:
        level = sea
    by_quantile = request["use_quantile"]
    if by_quantile and sea is not None:
        level, by_quantile = land_quantile(z, sea, request["quantile"]), False
    if not by_quantile and sea is not None and level <= sea:
        # The flattened sea lies exactly at the sea level and counts as land
        # there (land: height >= level): take the level just above it.
        level = sea + 1e-5 * max(highest - lowest, 1e-6)
    return level, by_quantile, (lowest, highest)


def trace(hf, request, strict=True):
    """LineArrays of the coastline that `request` asks for on `hf` (any thread).
    No line there is an error when `strict`, else an empty set (a retrace: the
    terrain has no coast at that level any more, and its curve says so)."""
    level, by_quantile, (lowest, highest) = level_of(hf, request)
    with core.coastline(hf, level, quantile=by_quantile) as pl:
        if pl.line_count == 0 and strict:
            # Not an empty curve without a word: say why.
            what = f"quantile {level:g}" if by_quantile else f"level {level:g}"
            raise SettingsError(f"no coastline at {what}: the terrain's heights are "
                                f"[{lowest:g}, {highest:g}] and no cell crosses it")
        return LineArrays(pl, unit_radius=True)


def to_local(nx, ny, world_size_xy):
    """Sample units (column, row, z) to the terrain's local frame."""
    wx, wy = world_size_xy

    def transform(x, y, z):
        return (x / (nx - 1) - 0.5) * wx, (y / (ny - 1) - 0.5) * wy, z
    return transform


def build_curve(lines, radius, transform, name="Coastline"):
    """Build steps of a coastline curve (a tube of `radius`, 0: a bare line);
    removed again if cancelled or failed. Returns the curve."""
    curve = new_curve(name, bevel=False)
    try:
        yield from fill_curve_steps(curve, lines, transform=transform)
    except BaseException:  # GeneratorExit too: a cancel leaves no curve behind
        bpy.data.curves.remove(curve)
        raise
    curve.bevel_depth = radius  # times each point's radius of 1
    return curve


def remember(obj, request, radius):
    """Records on coastline object `obj` what it was traced for."""
    obj[COAST_SETTINGS] = json.dumps({**request, "radius": radius})


def coastlines_of(terrain):
    """[(coastline object, its request with the terrain's sea now)] of a terrain."""
    s = terrain.fracterra_terrain
    out = []
    for child in terrain.children:
        if child.get("fracterra_kind") != KIND or child.type != "CURVE":
            continue
        text = child.get(COAST_SETTINGS)
        if not isinstance(text, str):
            continue  # made by an older add-on: nothing to retrace it by
        request = json.loads(text)
        out.append((child, {**request, "sea": s.sea, "sea_level": s.sea_level}))
    return out
