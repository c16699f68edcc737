# SPDX-License-Identifier: GPL-3.0-or-later
"""Reading objects back: is an object a fracterra terrain (or measurable at
all), a terrain's grid size, a library heightfield of its current vertex
heights, and the settings its mesh was built from (so that after a cancel, an
undo or a failure the sidebar shows the settings of the mesh that is there)."""

import array
import contextlib
import json
import zlib

import bpy
import numpy as np

from ... import core
from ...core import params
from ...core.params import grid_shape
from .curve import spline_nodes
from ..common.reporting import SettingsError


def active_object(context):
    """The active object, hidden or not (the 3D view's context gives None for a
    hidden one; the sidebar still edits it)."""
    obj = context.active_object
    if obj is None and getattr(context, "view_layer", None) is not None:
        obj = context.view_layer.objects.active
    return obj


def is_terrain(obj):
    return obj is not None and obj.type == "MESH" and obj.fracterra_terrain.is_terrain


def is_planet(obj):
    """Made by Add > Mesh > Fractal Planet."""
    return obj is not None and obj.type == "MESH" and obj.fracterra_planet.is_planet


def editable_settings(obj):
    """(settings, param list) of a terrain or a planet object (its PropertyGroup
    and the settings it stores), or None for any other object."""
    if is_terrain(obj):
        return obj.fracterra_terrain, params.TERRAIN_OBJECT_PARAMS
    if is_planet(obj):
        return obj.fracterra_planet, params.PLANET_OBJECT_PARAMS
    return None


def is_polyline(obj):
    """Made by Add > Curve > Fractal Polyline (a curve, or a point mesh for IFS)."""
    return obj is not None and obj.type in {"CURVE", "MESH"} and obj.fracterra_polyline.is_polyline


def is_measurable(obj):
    """Object > Measure works on terrains (H, D) and curves (eta, chi, gamma, D)."""
    return obj is not None and (is_terrain(obj) or obj.type == "CURVE")


def _planet_level(obj):
    """("Preview" or "Final", level) of what a planet object's mesh holds;
    ("Other", level) for a cube-sphere of another level (the settings were
    changed since, and not yet built); None for any other mesh (edited)."""
    settings = params.values_of(obj.fracterra_planet, params.PLANET_OBJECT_PARAMS)
    n = len(obj.data.vertices)
    for kind, values in (("Final", settings), ("Preview", params.planet_preview_values(settings))):
        if n == 6 * 4 ** values["level"] + 2:
            return kind, values["level"]
    level = next((k for k in range(13) if n == 6 * 4 ** k + 2), None)
    return ("Other", level) if level is not None else None


def mesh_level(obj):
    """("Preview" or "Final", nx, ny) of what a terrain object's mesh holds, or
    None when it is neither (edited, or built by an older add-on). For a
    planet: ("Preview" or "Final", level)."""
    if is_planet(obj):
        return _planet_level(obj)
    # By the settings the mesh was built from, as mesh_grid: with Auto Update
    # off, raised Detail Levels ask for another grid while the mesh is still
    # the Final it was ("Mesh: edited" there was a state that was not there).
    settings = built_settings(obj.data) or params.values_of(obj.fracterra_terrain)
    n = len(obj.data.vertices)
    final = grid_shape(settings)
    if n == final[0] * final[1]:
        return "Final", *final
    preview = grid_shape(params.preview_values(settings))
    if n == preview[0] * preview[1]:
        return "Preview", *preview
    return None


def mesh_grid(obj):
    """(nx, ny) of the grid a terrain object's mesh holds, by the settings it was
    built from (its Final or its Preview), or None (edited, or older): the
    settings shown may already ask for another size."""
    built = built_settings(obj.data) or params.values_of(obj.fracterra_terrain)
    n = len(obj.data.vertices)
    for values in (built, params.preview_values(built)):
        nx, ny = grid_shape(values)
        if nx * ny == n:
            return nx, ny
    return None


def terrain_grid_size(obj):
    """(nx, ny) of a fracterra terrain object whose mesh is still its grid (its Final or its Preview)."""
    level = mesh_level(obj)
    if level is None:
        nx, ny = grid_shape(params.values_of(obj.fracterra_terrain))
        raise SettingsError(f"'{obj.name}' has {len(obj.data.vertices)} vertices, not its {nx} x {ny} grid "
                            "(edited?); regenerate it first")
    return level[1], level[2]


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
    """The height of a terrain's flat sea (None without one), of its settings
    (a PropertyGroup): sea_height_of its Sea and Sea Level."""
    return sea_height_of(settings.sea, settings.sea_level, lowest)


def sea_height_of(sea, sea_level, lowest):
    """The height of a flat sea (None without one): Sea Level for sea HEIGHT,
    for a sea given as a FRACTION the terrain's lowest height, where the
    library flattened it (`lowest`: the minimum of its heights)."""
    if sea == "HEIGHT":
        return sea_level
    if sea == "FRACTION":
        return lowest
    return None


# The settings a terrain mesh was built from, as JSON in a custom property of
# the mesh: it travels with the mesh (undo restores both, a cancelled rebuild
# keeps the old mesh and so its settings).
BUILT_FROM = "fracterra_settings"
_restoring = []


def remember_settings(mesh, values):
    """Records on `mesh` the settings (a dict, params.values_of) it was just built from."""
    mesh[BUILT_FROM] = json.dumps(values)


def built_settings(mesh):
    """{name: value} the mesh was built from, or None (a mesh made before this was recorded)."""
    text = mesh.get(BUILT_FROM) if mesh is not None else None
    return json.loads(text) if isinstance(text, str) else None


def _as_built(values, kind, planet):
    """What of settings `values` a mesh of `kind` (Preview or Final) is made from:
    a Preview's its Preview level, never the other level's setting."""
    if planet:
        values = params.planet_preview_values(values) if kind == "Preview" else values
        other = "preview_level"
    else:
        values = params.preview_values(values) if kind == "Preview" else values
        other = "preview_levels"
    return {k: tuple(v) if isinstance(v, (list, tuple)) else v for k, v in values.items() if k != other}


def out_of_date(obj, mesh=None):
    """The labels of the settings of terrain or planet `obj` that no longer match
    those its mesh (or `mesh`: its kept Final) was built from ([]: they match,
    or the mesh recorded none)."""
    editable = editable_settings(obj)
    mesh = obj.data if mesh is None else mesh
    built = built_settings(mesh) if editable is not None else None
    level = ("Final",) if built is not None and mesh is not obj.data else (mesh_level(obj) if built else None)
    if level is None:
        return []
    settings, param_list = editable
    planet = is_planet(obj)
    now = _as_built(params.values_of(settings, param_list), level[0], planet)
    then = _as_built({**now, **built}, level[0], planet)
    by_name = {p.name: p for p in param_list}
    return [by_name[k].label for k in now if k in by_name and now[k] != then.get(k)]


def restoring():
    """True while restore_settings (or quietly) writes settings: no Auto Update may run then."""
    return bool(_restoring)


@contextlib.contextmanager
def quietly(obj):
    """Settings of `obj` written inside this block run no Auto Update."""
    _restoring.append(obj.name)
    try:
        yield
    finally:
        _restoring.pop()


def restore_settings(obj):
    """Puts the settings its mesh was built from back into terrain or planet
    `obj`'s settings (after a cancel, an undo or a failure); returns the names changed."""
    editable = editable_settings(obj)
    if editable is None:
        return []
    built = built_settings(obj.data)
    if built is None:
        return []
    settings, param_list = editable
    changed = []
    with quietly(obj):
        for p in param_list:  # the preset before the passes it fills
            if p.name in built:
                value = tuple(built[p.name]) if p.kind == "vector" else built[p.name]
                current = getattr(settings, p.name)
                if (tuple(current) if p.kind == "vector" else current) != value:
                    setattr(settings, p.name, value)
                    changed.append(p.name)
    return changed


@bpy.app.handlers.persistent
def restore_after_undo(*_args):
    """undo_post / redo_post: an undone Regenerate brings the old mesh back, but a
    sidebar edit is an undo step of its own, so the settings could stay newer
    than the mesh. Every terrain and planet gets the settings of its mesh back."""
    for obj in bpy.data.objects:
        restore_settings(obj)
