"""Curves and point clouds from library polylines, and library polylines from
curves, with whole-array copies (foreach_get / foreach_set), never a Python
loop over points."""

import bpy
import numpy as np

from .. import core


def curve_from_polylines(name, pl, bevel, transform=None, unit_radius=False):
    """A new curve datablock with one POLY spline per line of `pl`, radii from the library.

    transform: None or f(x, y, z) -> (x, y, z) on float64 arrays (e.g. sample
    units to local coordinates). unit_radius: every point's radius is 1 (lines
    the library gives no radii, e.g. coastlines), so bevel_depth is the radius.
    """
    curve = bpy.data.curves.new(name, "CURVE")
    curve.dimensions = "3D"
    if bevel:
        curve.bevel_depth = 1.0  # times each point's radius
        curve.bevel_resolution = 2
        curve.use_fill_caps = True
    xyz = np.asarray(pl.xyz(), dtype=np.float64).reshape(-1, 3)
    radii = np.ones(pl.vertex_count, np.float32) if unit_radius else np.asarray(pl.radii(), dtype=np.float32)
    offsets = pl.offsets()
    if transform:
        xyz = np.stack(transform(xyz[:, 0], xyz[:, 1], xyz[:, 2]), axis=1)
    co = np.ones((len(xyz), 4), dtype=np.float32)  # x, y, z, w = 1
    co[:, :3] = xyz
    for a, b in zip(offsets[:-1], offsets[1:]):
        if b - a < 2:
            continue
        spline = curve.splines.new("POLY")
        spline.points.add(b - a - 1)
        spline.points.foreach_set("co", co[a:b].ravel())
        spline.points.foreach_set("radius", radii[a:b])
    return curve


def point_cloud_from_polylines(name, pl):
    """A mesh of loose vertices, one per polyline vertex (IFS point sets)."""
    mesh = bpy.data.meshes.new(name)
    xyz = np.asarray(pl.xyz(), dtype=np.float32)
    mesh.vertices.add(len(xyz) // 3)
    mesh.vertices.foreach_set("co", xyz)
    mesh.update()
    return mesh


def link_new_object(context, name, data, matrix):
    """A new object holding `data`, linked to the active collection, selected and active."""
    obj = bpy.data.objects.new(name, data)
    obj.matrix_world = matrix
    context.collection.objects.link(obj)
    for other in context.selected_objects:
        other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
    return obj


def spline_nodes(spline):
    """(n, 3) float64 array of a spline's control points (Bezier or poly/NURBS)."""
    if spline.type == "BEZIER":
        pts, width = spline.bezier_points, 3
    else:
        pts, width = spline.points, 4  # x, y, z, w
    co = np.empty(width * len(pts), dtype=np.float32)
    pts.foreach_get("co", co)
    return co.reshape(-1, width)[:, :3].astype(np.float64)


def spline_radii(spline):
    pts = spline.bezier_points if spline.type == "BEZIER" else spline.points
    radius = np.empty(len(pts), dtype=np.float32)
    pts.foreach_get("radius", radius)
    return radius.astype(np.float64)


def curve_polylines(obj, matrix, shift=(0.0, 0.0, 0.0)):
    """A core.Polylines of a curve object's splines of 2 or more points, each point
    mapped by the 4x4 `matrix` then moved by `shift`, with radius times the bevel
    depth; None when no spline has 2 points."""
    m = np.array(matrix, dtype=np.float64)
    depth = max(obj.data.bevel_depth, 0.0)
    lines, radii = [], []
    for spline in obj.data.splines:
        nodes = spline_nodes(spline)
        if len(nodes) >= 2:
            lines.append(nodes @ m[:3, :3].T + m[:3, 3] + np.asarray(shift, dtype=np.float64))
            radii.append(spline_radii(spline) * depth)
    if not lines:
        return None
    offsets = np.cumsum([0] + [len(line) for line in lines], dtype=np.int64)
    return core.Polylines.from_arrays(np.concatenate(lines).ravel(), np.concatenate(radii), offsets)
