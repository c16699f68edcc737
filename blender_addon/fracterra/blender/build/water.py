# SPDX-License-Identifier: GPL-3.0-or-later
"""Rivers and Lakes of a terrain object: the library's network (core.rivers.
WaterArrays, traced by the pipeline's last stage) as Blender objects parented
to the terrain, in its local frame:
    Rivers  one curve, a POLY spline per river segment (cut where its ribbon
            would reach into a lake: one spline per part), each point's radius
            half the river's width; its bevel is a flat ellipse (a ribbon in the
            bed, not a pipe on the land), so the width follows the discharge;
    Lakes   one flat mesh: the grid cells of each lake at its level, cut to
            where the water is deeper than the network's minimum depth (1% of
            the relief by default), so no water lies flush with the ground;
    Sea     one flat mesh at the sea's level over the sea's cells, cut so too.
All share the Fracterra Water material. Each carries its kind in
obj["fracterra_kind"]; a re-run removes the terrain's old ones first, so
nothing is duplicated.
"""

import bpy
import numpy as np

from ...core.grid import grid_size
from ...core.rivers import LAND, SEA
from ...core.water_surface import depth_triangles, split_13
from .mesh import loop_total_writable
from .objects import is_terrain

MATERIAL_NAME = "Fracterra Water"
KINDS = ("RIVERS", "LAKES", "SEA", "RIVER_PROFILE")
# Objects a terrain owns (water, and its coastline): with one of them active,
# the sidebar edits the terrain's settings.
OWNED_KINDS = KINDS + ("COASTLINE",)
# The river's cross-section: an ellipse as high as this fraction of its width
# (the POV-Ray scenes' FT_River_Flat), a ribbon lying in its bed.
RIVER_FLAT = 0.3
_PROFILE_POINTS = 16  # points around the ellipse

# New terrains: the water their build produced, until the operator has made
# the object it belongs to (keyed by the mesh's pointer).
_pending = {}


def remember(mesh, water):
    _pending[mesh.as_pointer()] = water


def take(mesh):
    return _pending.pop(mesh.as_pointer(), None)


def terrain_of(obj):
    """The terrain whose settings the sidebar shows for `obj`: `obj` itself, or
    the terrain a water object or a coastline belongs to (its parent); None."""
    if is_terrain(obj):
        return obj
    if obj is not None and obj.get("fracterra_kind") in OWNED_KINDS and is_terrain(obj.parent):
        return obj.parent
    return None


def water_objects(terrain):
    """The terrain's water objects (children with a water kind)."""
    return [c for c in terrain.children if c.get("fracterra_kind") in KINDS]


def remove_water(terrain):
    """Removes the terrain's water objects and their data."""
    for obj in water_objects(terrain):
        data = obj.data
        bpy.data.objects.remove(obj)
        _remove_data(data)


def water_material():
    """The water of rivers, lakes and sea (made once per file)."""
    mat = bpy.data.materials.get(MATERIAL_NAME)
    if mat is not None:
        return mat
    mat = bpy.data.materials.new(MATERIAL_NAME)
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes.get("Principled BSDF")
    bsdf.inputs["Base Color"].default_value = (0.02, 0.09, 0.16, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.08
    mat.diffuse_color = (0.05, 0.2, 0.35, 1.0)  # Solid view
    return mat


class _Frame:
    """World units of the network (x = column x spacing) to the terrain's local frame."""

    def __init__(self, water, world_size):
        wx, wy = grid_size(world_size, water.nx, water.ny)
        self.wx, self.wy = wx, wy
        self.kx = wx / ((water.nx - 1) * water.spacing)
        self.ky = wy / ((water.ny - 1) * water.spacing)

    def xy(self, x, y):
        return x * self.kx - 0.5 * self.wx, y * self.ky - 0.5 * self.wy


def _remove_data(data):
    if data is not None and data.users == 0:
        (bpy.data.curves if isinstance(data, bpy.types.Curve) else bpy.data.meshes).remove(data)


def put(terrain, kind, name, data, collection):
    """The terrain's object of `kind` holding `data`: the one there is (its data
    swapped, its materials kept: a re-run keeps what the user set), else a new
    one parented to the terrain with the water material."""
    obj = next((c for c in water_objects(terrain) if c.get("fracterra_kind") == kind), None)
    if obj is None:
        obj = bpy.data.objects.new(name, data)
        collection.objects.link(obj)
        obj.parent = terrain  # in the terrain's frame (identity parent inverse)
        obj["fracterra_kind"] = kind
        if kind != "RIVER_PROFILE":
            data.materials.append(water_material())
        return obj
    old = obj.data
    for mat in old.materials:
        data.materials.append(mat)
    obj.data = data
    _remove_data(old)
    return obj


def _profile(terrain, collection):
    """The rivers' bevel object: a flat ellipse, width 2 x height 2 RIVER_FLAT,
    scaled by each point's radius; hidden."""
    curve = bpy.data.curves.new(f"{terrain.name} River Profile", "CURVE")
    spline = curve.splines.new("POLY")
    t = np.linspace(0.0, 2.0 * np.pi, _PROFILE_POINTS, endpoint=False)
    # Blender lays a bevel object's x across the curve (horizontal with Z_UP) and its y up
    # (measured on the evaluated mesh: x ran across, so the ribbon stood on edge).
    co = np.stack([np.cos(t), RIVER_FLAT * np.sin(t), np.zeros_like(t), np.ones_like(t)], axis=1)
    spline.points.add(len(t) - 1)
    spline.points.foreach_set("co", co.astype(np.float32).ravel())
    spline.use_cyclic_u = True
    obj = put(terrain, "RIVER_PROFILE", curve.name, curve, collection)
    obj.hide_viewport = obj.hide_render = True
    return obj


def _rivers(terrain, water, frame, collection):
    curve = bpy.data.curves.new(f"{terrain.name} Rivers", "CURVE")
    curve.dimensions = "3D"
    curve.twist_mode = "Z_UP"  # the ribbon stays level across the valley
    # The lines as drawn: a ribbon over a lake would stand its height over the lake's surface.
    xyz = water.ribbon_xyz
    x, y = frame.xy(xyz[:, 0], xyz[:, 1])
    co = np.stack([x, y, xyz[:, 2], np.ones(len(x))], axis=1).astype(np.float32)
    radii = (water.ribbon_radii * frame.kx).astype(np.float32)
    for a, b in zip(water.ribbon_offsets[:-1], water.ribbon_offsets[1:]):
        if b - a < 2:
            continue
        spline = curve.splines.new("POLY")
        spline.points.add(int(b - a) - 1)
        spline.points.foreach_set("co", co[a:b].ravel())
        spline.points.foreach_set("radius", radii[a:b])
    curve.bevel_mode = "OBJECT"
    curve.bevel_object = _profile(terrain, collection)
    curve.use_fill_caps = True
    return put(terrain, "RIVERS", curve.name, curve, collection)


def _triangle_mesh(name, frame, water, xy, z):
    """A mesh of separate triangles: xy (n, 3, 2) grid coordinates, z (n,) heights."""
    n = len(z)
    x, y = frame.xy(xy[:, :, 0].ravel() * water.spacing, xy[:, :, 1].ravel() * water.spacing)
    co = np.stack([x, y, np.repeat(z, 3)], axis=1).astype(np.float32)
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(co))
    mesh.vertices.foreach_set("co", co.ravel())
    mesh.loops.add(3 * n)
    mesh.loops.foreach_set("vertex_index", np.arange(3 * n, dtype=np.int32))
    mesh.polygons.add(n)
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * n, 3, dtype=np.int32))
    if loop_total_writable():
        mesh.polygons.foreach_set("loop_total", np.full(n, 3, dtype=np.int32))
    mesh.update(calc_edges=True)
    return mesh


def _drawn_split(terrain, water):
    """split_13 of the terrain's mesh (the cells Blender draws split along
    corners 1-3), or None when the mesh is not the network's grid."""
    vertices = terrain.data.vertices
    if len(vertices) != water.nx * water.ny:
        return None
    co = np.empty(3 * len(vertices), dtype=np.float32)
    vertices.foreach_get("co", co)
    return split_13(co.reshape(water.ny, water.nx, 3))


def _depth_mesh(name, water, frame, heights, wet, level_of, split13):
    """The water over the grid cells with a wet corner (wet: (ny, nx) bool), each at
    level_of(its wet corner's label), cut to where it is deeper than water.min_depth;
    None when nothing is that deep."""
    corner = wet[:-1, :-1] | wet[:-1, 1:] | wet[1:, :-1] | wet[1:, 1:]
    rows, cols = np.nonzero(corner)
    if rows.size == 0:
        return None
    # Each cell's label: that of a wet corner (the corners' labels agree: two
    # lakes never touch, 8-connected cells under water are one lake).
    labels = water.mask
    lab = np.full(rows.size, LAND, dtype=np.int64)
    for dy, dx in ((0, 0), (0, 1), (1, 0), (1, 1)):
        w = wet[rows + dy, cols + dx]
        lab = np.where((lab == LAND) & w, labels[rows + dy, cols + dx], lab)
    xy, z = depth_triangles(heights, rows, cols, np.asarray(level_of(lab), dtype=np.float64), water.min_depth,
                            split13)
    return _triangle_mesh(name, frame, water, xy, z) if len(z) else None


def build_water(terrain, water, heights=None):
    """Makes the terrain's water objects those of `water` (None: removes them):
    an object of a kind already there gets the new data (nothing duplicated),
    one no longer wanted goes. `heights`: (ny, nx) terrain heights, for the
    sea's level (its highest cell: the landform flattened the sea there).
    Returns a summary."""
    if water is None:
        remove_water(terrain)
        return ""
    collection = terrain.users_collection[0] if terrain.users_collection else bpy.context.collection
    frame = _Frame(water, terrain.fracterra_terrain.world_size)
    made, kept = [], set()
    if water.segment_count:
        _rivers(terrain, water, frame, collection)
        kept |= {"RIVERS", "RIVER_PROFILE"}
        made.append(f"{water.segment_count} river segments")
    lakes = water.mask >= 0
    sea = water.mask == SEA
    split13 = _drawn_split(terrain, water) if heights is not None and (lakes.any() or sea.any()) else None
    mesh = None
    if lakes.any() and heights is not None:
        levels = water.levels
        mesh = _depth_mesh(f"{terrain.name} Lakes", water, frame, heights, lakes, lambda lab: levels[lab], split13)
    if mesh is not None:
        put(terrain, "LAKES", mesh.name, mesh, collection)
        kept.add("LAKES")
        made.append(f"{water.lake_count} lakes")
    mesh = None
    if sea.any() and heights is not None:
        # The landform flattens the sea's floor at the sea's level: the water
        # stands just over the minimum depth (1.1 x) above its highest floor
        # cell, so the floor is under more than that and the cut coast lies
        # 0.1 x the minimum depth over it (1e-3 of the relief at the default;
        # the old sea stood 1e-4 over it): the coast stays where the landform
        # put it.
        level = float(heights[sea].max()) + 1.1 * water.min_depth
        mesh = _depth_mesh(f"{terrain.name} Sea", water, frame, heights, sea, lambda lab: np.full(len(lab), level),
                           split13)
    if mesh is not None:
        put(terrain, "SEA", mesh.name, mesh, collection)
        kept.add("SEA")
        made.append("the sea")
    for obj in water_objects(terrain):
        if obj.get("fracterra_kind") not in kept:
            data = obj.data
            bpy.data.objects.remove(obj)
            _remove_data(data)
    return ", ".join(made) or "no water"
