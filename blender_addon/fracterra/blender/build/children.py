# SPDX-License-Identifier: GPL-3.0-or-later
"""The objects that hang off a terrain and follow it when it re-generates, in
the terrain's own job (one bar, one Esc): its coastlines are retraced on the
new heights, and a lightning bolt that struck it is aimed again at the new
surface under its end. (Its water comes from the library's pipeline with the
terrain itself: water.py.)

The job's three parts, as jobs.py splits work:
    plan(terrain)              main thread: what there is to re-make
    remake(plan, g, ...)       worker thread: the new lines (bpy-free)
    build_steps / commit       main thread: new curves made aside in steps,
                               then swapped in at once (a cancel before the
                               commit leaves every child as it was)
"""

import json

import bpy
import numpy as np

from ... import core
from ...core import params
from ...core.grid import grid_size
from . import coastline
from .objects import is_planet, is_polyline, is_terrain, mesh_grid, quietly
from ..common.jobs import Job
from .polyline import build_data, generate_lines, swap_data

# On a polyline object: it struck this terrain (its parent) and is re-aimed with it.
STRIKE = "fracterra_strike"


def struck(obj):
    """True for a polyline that struck its parent terrain's surface."""
    return bool(obj.get(STRIKE)) and is_polyline(obj) and obj.type == "CURVE" and obj.parent is not None


def plan(terrain):
    """[(kind, object name, what it needs)] of the children to re-make."""
    out = [("COASTLINE", child.name, request) for child, request in coastline.coastlines_of(terrain)]
    for child in terrain.children:
        if struck(child):
            values = params.values_of(child.fracterra_polyline, params.POLYLINE_PARAMS)
            # The bolt's frame to the terrain's, as numbers the worker can use.
            to_terrain = np.array(terrain.matrix_world.inverted() @ child.matrix_world, dtype=np.float64)
            out.append(("LIGHTNING", child.name, (values, to_terrain)))
    return out


def surface_z(z, world_size, x, y):
    """The height of grid `z` ((ny, nx), spanning the terrain's local frame) at
    local (x, y), bilinear between its four nearest samples."""
    ny, nx = z.shape
    wx, wy = grid_size(world_size, nx, ny)
    c = float(np.clip((x / wx + 0.5) * (nx - 1), 0, nx - 1))
    r = float(np.clip((y / wy + 0.5) * (ny - 1), 0, ny - 1))
    c0, r0 = min(int(c), nx - 2), min(int(r), ny - 2)
    fc, fr = c - c0, r - r0
    top = z[r0, c0] * (1 - fc) + z[r0, c0 + 1] * fc
    bottom = z[r0 + 1, c0] * (1 - fc) + z[r0 + 1, c0 + 1] * fc
    return float(top * (1 - fr) + bottom * fr)


def aimed(values, to_terrain, z, world_size):
    """(start, end) of a bolt (its own frame) moved so that its end stands on the
    surface `z` under it, the start moved by as much (its length kept)."""
    start, end = np.array(values["start"], dtype=np.float64), np.array(values["end"], dtype=np.float64)
    local = to_terrain @ np.append(end, 1.0)
    hit = np.array([local[0], local[1], surface_z(z, world_size, local[0], local[1]), 1.0])
    new_end = (np.linalg.inv(to_terrain) @ hit)[:3]
    return tuple(start + (new_end - end)), tuple(new_end)


def remake(items, g, world_size, threads):
    """[(kind, name, lines, extra)]: the new lines of each planned child on the
    built grid `g` (core.grid.GridArrays). Worker thread."""
    if not items:
        return []
    z = np.frombuffer(g.co, dtype=np.float32)[2::3].reshape(g.ny, g.nx)
    out = []
    with core.Heightfield.from_values(g.nx, g.ny, z.ravel()) as hf:
        for kind, name, need in items:
            if kind == "COASTLINE":
                out.append((kind, name, coastline.trace(hf, need, strict=False), need))
            else:
                values, to_terrain = need
                start, end = aimed(values, to_terrain, z, world_size)
                values = {**values, "start": start, "end": end}
                out.append((kind, name, generate_lines(values, [start, end], threads), values))
    return out


def build_steps(remade, terrain_values, nx, ny):
    """Build steps of the children's new data, made aside; returns
    [(name, data, extra)] for commit(). A cancel removes what was made."""
    made = []
    transform = coastline.to_local(nx, ny, grid_size(terrain_values["world_size"], nx, ny))
    try:
        for kind, name, lines, extra in remade:
            obj = bpy.data.objects.get(name)
            if obj is None:
                continue
            if kind == "COASTLINE":
                data = yield from coastline.build_curve(lines, obj.data.bevel_depth, transform, obj.data.name)
            else:
                data, _summary = yield from build_data(extra, lines)
            made.append((name, data, extra))
    except BaseException:  # GeneratorExit too
        for _name, data, _extra in made:
            bpy.data.curves.remove(data)
        raise
    return made


def commit(made):
    """Swaps each child's new data in (no steps: all of them or none); a
    summary ("2 children re-made") or ""."""
    for name, data, extra in made:
        obj = bpy.data.objects[name]
        swap_data(obj, data)
        if obj.get("fracterra_kind") == coastline.KIND:
            continue
        settings = obj.fracterra_polyline
        with quietly(obj):  # the bolt's own Auto Update must not rebuild it again
            settings.start, settings.end = extra["start"], extra["end"]
    return f"{len(made)} {'child' if len(made) == 1 else 'children'} re-made" if made else ""


class _Grid:
    """The co, nx, ny of a terrain mesh as remake() reads a built grid."""

    def __init__(self, obj, nx, ny):
        self.nx, self.ny = nx, ny
        self.co = np.empty(3 * nx * ny, dtype=np.float32)
        obj.data.vertices.foreach_get("co", self.co)


def follow_job(terrain, threads):
    """A progress.Job re-making the children of `terrain` on the mesh it holds
    now (Back to Final); its value is a summary."""
    items = plan(terrain)
    values = params.values_of(terrain.fracterra_terrain)
    grid = mesh_grid(terrain)
    if grid is None or not items:
        return Job("Children", lambda _progress: [], lambda _remade: _done(""))
    g = _Grid(terrain, *grid)

    def build(remade):
        made = yield from build_steps(remade, values, g.nx, g.ny)
        return commit(made)
    return Job("Re-making the terrain's children", lambda _progress: remake(items, g, values["world_size"], threads),
               build)


def _done(value):
    return value
    yield  # noqa: unreachable - a generator


# What follow_visibility last saw of each terrain and planet: {pointer: (hidden, viewport, render)}.
_SEEN = {}


@bpy.app.handlers.persistent
def follow_visibility(scene, depsgraph=None):
    """depsgraph_update_post (Disable in Viewports or in Renders, a script's
    hide_set), and every VISIBILITY_POLL seconds from a timer (the eye and H
    change the view layer's bases, which runs no depsgraph handler): a
    terrain or planet hidden hides its children (water, sea, coastlines, a
    bolt) alike, and shown again shows them; a child hidden on its own while
    its parent stays as it was keeps its own state."""
    view_layer = depsgraph.view_layer if depsgraph is not None else bpy.context.view_layer
    if scene is None or view_layer is None:
        return
    for obj in scene.objects:
        if not (is_terrain(obj) or is_planet(obj)):
            continue
        try:
            state = (obj.hide_get(view_layer=view_layer), obj.hide_viewport, obj.hide_render)
        except RuntimeError:  # not in this view layer
            continue
        before = _SEEN.get(obj.as_pointer())
        _SEEN[obj.as_pointer()] = state
        if before is None or before == state:
            continue
        for child in obj.children:
            if child.get("fracterra_kind") == "RIVER_PROFILE":
                continue  # the rivers' bevel shape: always hidden
            try:
                if state[0] != before[0] and child.hide_get(view_layer=view_layer) != state[0]:
                    child.hide_set(state[0], view_layer=view_layer)
            except RuntimeError:
                pass
            if state[1] != before[1] and child.hide_viewport != state[1]:
                child.hide_viewport = state[1]
            if state[2] != before[2] and child.hide_render != state[2]:
                child.hide_render = state[2]


VISIBILITY_POLL = 0.25


def poll_visibility():
    """The timer's side of follow_visibility (bpy.app.timers: the seconds to the next call)."""
    context = bpy.context
    scene = getattr(context, "scene", None)
    if scene is not None:
        follow_visibility(scene, None)
    return VISIBILITY_POLL


def remember_strike(obj):
    """Marks a new polyline object whose end struck its parent terrain."""
    obj[STRIKE] = json.dumps(True)
