# SPDX-License-Identifier: GPL-3.0-or-later
"""Filling Blender meshes from the library's grid arrays with foreach_set."""

import array

import bpy
import numpy as np

from . import huge_pages


def loop_total_writable():
    # Blender 4.0 derives polygon sizes from loop_start; 3.x needs loop_total.
    return not bpy.types.MeshPolygon.bl_rna.properties["loop_total"].is_readonly


def fill_grid_mesh_steps(mesh, g, smooth=True):
    """Replaces the geometry of `mesh` by the grid `g` (core.grid.GridArrays),
    yielding the fraction done after each bulk copy (a progress bar's steps;
    each copy of a large grid takes a good part of a second).

    Vertices, edges, loops and polygons are all given, so Blender derives
    nothing (update(calc_edges=True) would double the time).
    """
    mesh.clear_geometry()
    mesh.vertices.add(g.vertex_count)
    mesh.edges.add(g.edge_count)
    mesh.loops.add(g.loop_count)
    mesh.polygons.add(g.face_count)
    huge_pages.advise(mesh.vertices, mesh.edges, mesh.loops, mesh.polygons)
    yield 0.1
    mesh.vertices.foreach_set("co", g.co)
    yield 0.2
    mesh.edges.foreach_set("vertices", g.edge_vertices)
    yield 0.3
    mesh.loops.foreach_set("vertex_index", g.loop_vertices)
    yield 0.45
    mesh.loops.foreach_set("edge_index", g.loop_edges)
    yield 0.6
    mesh.polygons.foreach_set("loop_start", g.loop_starts)
    if loop_total_writable():
        mesh.polygons.foreach_set("loop_total", g.loop_totals)
    yield 0.7
    set_uvs(mesh, g.uv)
    yield 0.8
    set_smooth(mesh, smooth)  # (with the UVs one step of 2.6 s at 4097^2, load 4-6)
    yield 0.85
    mesh.update()  # nothing left to derive: it only tags the mesh for redrawing


def fill_quad_mesh_steps(mesh, co, loop_vertices, smooth=True):
    """Replaces the geometry of `mesh` by quads: `co` 3 floats per vertex,
    `loop_vertices` 4 indices per quad (a closed mesh, e.g. a planet's
    cube-sphere); Blender derives the edges. Yields the fraction done."""
    faces = len(loop_vertices) // 4
    mesh.clear_geometry()
    mesh.vertices.add(len(co) // 3)
    mesh.loops.add(4 * faces)
    mesh.polygons.add(faces)
    yield 0.1
    mesh.vertices.foreach_set("co", co)
    mesh.loops.foreach_set("vertex_index", loop_vertices)
    yield 0.4
    mesh.polygons.foreach_set("loop_start", np.arange(0, 4 * faces, 4, dtype=np.uint32))
    if loop_total_writable():
        mesh.polygons.foreach_set("loop_total", np.full(faces, 4, dtype=np.uint32))
    set_smooth(mesh, smooth)
    yield 0.6
    mesh.update(calc_edges=True)


def fill_quad_mesh(mesh, co, loop_vertices, smooth=True):
    """fill_quad_mesh_steps in one go."""
    for _fraction in fill_quad_mesh_steps(mesh, co, loop_vertices, smooth):
        pass


def swap_mesh(obj, new):
    """Gives `obj` the mesh `new` in place of its old one: the old one's
    materials when it has any (what the user set stays), else the new one's
    own; the old mesh goes when nothing else uses it, and `new` takes its name."""
    old = obj.data
    if len(old.materials):
        new.materials.clear()
        for material in old.materials:
            new.materials.append(material)
    obj.data = new
    if old.users == 0:
        name = old.name
        bpy.data.meshes.remove(old)
        new.name = name


def fill_grid_mesh(mesh, g, smooth=True):
    """fill_grid_mesh_steps in one go."""
    for _fraction in fill_grid_mesh_steps(mesh, g, smooth):
        pass


UV_NAME = "UVMap"


def set_uvs(mesh, uv):
    """Adds (uv: array of 2 floats per loop) or removes (uv None) the grid's UV map."""
    layer = mesh.uv_layers.get(UV_NAME)
    if uv is None:
        if layer is not None:
            mesh.uv_layers.remove(layer)
        return
    if layer is None:
        layer = mesh.uv_layers.new(name=UV_NAME, do_init=False)
        huge_pages.advise(layer.data)
    layer.data.foreach_set("uv", uv)


def set_smooth(mesh, smooth):
    n = len(mesh.polygons)
    if n and mesh.polygons[0].use_smooth == smooth and mesh.polygons[n - 1].use_smooth == smooth:
        return
    mesh.polygons.foreach_set("use_smooth", array.array("b", [1 if smooth else 0]) * n)


def rewrite_positions(mesh, co):
    """Rewrites every vertex position with one foreach_set (topology untouched)."""
    mesh.vertices.foreach_set("co", co)
    mesh.update()


# Point attributes for materials (Attribute node, type Geometry/Instancer: the name):
HEIGHT_ATTRIBUTE = "fracterra_height"  # 0 at the lowest vertex, 1 at the highest
SLOPE_ATTRIBUTE = "fracterra_slope"  # 0 flat, 1 vertical: the slope angle / 90 degrees


def set_point_attributes(mesh, arrays):
    """Writes float point attributes {name: one value per vertex}, made when missing."""
    for name, values in arrays.items():
        layer = mesh.attributes.get(name)
        if layer is None:
            layer = mesh.attributes.new(name, "FLOAT", "POINT")
            huge_pages.advise(layer.data)
        layer.data.foreach_set("value", np.ascontiguousarray(values, dtype=np.float32).ravel())


def set_height_slope(mesh, height, slope):
    """Writes the height and slope attributes of a grid mesh (core.grid.height_slope)."""
    set_point_attributes(mesh, {HEIGHT_ATTRIBUTE: height, SLOPE_ATTRIBUTE: slope})
