# SPDX-License-Identifier: GPL-3.0-or-later
"""Where a new polyline's base meets a terrain: a bolt added over a fractal
terrain strikes its surface, not the plane z = 0 inside the mountain."""

from mathutils import Vector

from .objects import is_terrain


def surface_below(context, point):
    """(world point, terrain): the highest point of a fractal terrain's surface
    straight below (or above) world point `point` (a Vector), and that terrain;
    (None, None) when no terrain lies under it."""
    depsgraph = context.evaluated_depsgraph_get()
    best, terrain = None, None
    for obj in context.visible_objects:
        if not is_terrain(obj):
            continue
        to_local = obj.matrix_world.inverted()
        local = to_local @ point
        top = max(c[2] for c in obj.bound_box) + 1.0
        down = (to_local.to_3x3() @ Vector((0.0, 0.0, -1.0))).normalized()
        hit, where, _normal, _face = obj.ray_cast(Vector((local.x, local.y, top)), down, depsgraph=depsgraph)
        if hit:
            world = obj.matrix_world @ where
            if best is None or world.z > best.z:
                best, terrain = world, obj
    return best, terrain


def strike_base(context, matrix, start, end):
    """(start, end, terrain) in the frame `matrix` (the new object's world
    matrix) with the end moved onto the surface of the terrain under it and
    the start moved by as much, so the bolt keeps its length above the
    ground; unchanged, and terrain None, with no terrain below."""
    end_world = matrix @ Vector(end)
    hit, terrain = surface_below(context, end_world)
    if hit is None:
        return start, end, None
    new_end = matrix.inverted() @ hit
    shift = new_end - Vector(end)
    return tuple(Vector(start) + shift), tuple(new_end), terrain
