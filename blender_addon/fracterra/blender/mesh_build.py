"""Filling Blender meshes from the library's grid arrays with foreach_set."""

import array

import bpy


def _loop_total_writable():
    # Blender 4.0 derives polygon sizes from loop_start; 3.x needs loop_total.
    return not bpy.types.MeshPolygon.bl_rna.properties["loop_total"].is_readonly


def fill_grid_mesh(mesh, g, smooth=True):
    """Replaces the geometry of `mesh` by the grid `g` (core.grid.GridArrays).

    Vertices, edges, loops and polygons are all given, so Blender derives
    nothing (update(calc_edges=True) would double the time).
    """
    mesh.clear_geometry()
    mesh.vertices.add(g.vertex_count)
    mesh.edges.add(g.edge_count)
    mesh.loops.add(g.loop_count)
    mesh.polygons.add(g.face_count)
    mesh.vertices.foreach_set("co", g.co)
    mesh.edges.foreach_set("vertices", g.edge_vertices)
    mesh.loops.foreach_set("vertex_index", g.loop_vertices)
    mesh.loops.foreach_set("edge_index", g.loop_edges)
    mesh.polygons.foreach_set("loop_start", g.loop_starts)
    if _loop_total_writable():
        mesh.polygons.foreach_set("loop_total", g.loop_totals)
    set_uvs(mesh, g.uv)
    set_smooth(mesh, smooth)
    mesh.update()


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
