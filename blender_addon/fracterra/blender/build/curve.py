# SPDX-License-Identifier: GPL-3.0-or-later
"""Curves and point clouds from library polylines, and library polylines from
curves, with whole-array copies (foreach_get / foreach_set), never a Python
loop over points."""

import bpy
import numpy as np

from ... import core


class LineArrays:
    """A library polyline set copied out into numpy arrays (in any thread, e.g. a
    job's worker), so the handle can be freed before Blender data is built:
    xyz (n, 3) float64, radii (n,) float32, offsets (lines + 1,)."""

    def __init__(self, pl, unit_radius=False):
        self.xyz = np.asarray(pl.xyz(), dtype=np.float64).reshape(-1, 3)
        self.radii = np.ones(pl.vertex_count, np.float32) if unit_radius else np.asarray(pl.radii(), dtype=np.float32)
        self.offsets = list(pl.offsets())
        self.line_count, self.vertex_count = pl.line_count, pl.vertex_count


def new_curve(name, bevel):
    """An empty 3D curve datablock; with `bevel`, a round tube of each point's radius."""
    curve = bpy.data.curves.new(name, "CURVE")
    curve.dimensions = "3D"
    if bevel:
        curve.bevel_depth = 1.0  # times each point's radius
        curve.bevel_resolution = 2
        curve.use_fill_caps = True
    return curve


def fill_curve_steps(curve, lines, transform=None, points_per_step=100_000):
    """Adds one POLY spline per line of `lines` (LineArrays) to `curve`, yielding
    the fraction done about every `points_per_step` points (build steps of a
    progress.Job: a long curve does not freeze the window in one go).

    transform: None or f(x, y, z) -> (x, y, z) on float64 arrays (e.g. sample
    units to local coordinates)."""
    xyz = lines.xyz
    if transform:
        xyz = np.stack(transform(xyz[:, 0], xyz[:, 1], xyz[:, 2]), axis=1)
    co = np.ones((len(xyz), 4), dtype=np.float32)  # x, y, z, w = 1
    co[:, :3] = xyz
    offsets, radii = lines.offsets, lines.radii
    total, since = max(len(xyz), 1), 0
    for a, b in zip(offsets[:-1], offsets[1:]):
        if b - a < 2:
            continue
        spline = curve.splines.new("POLY")
        spline.points.add(b - a - 1)
        spline.points.foreach_set("co", co[a:b].ravel())
        spline.points.foreach_set("radius", radii[a:b])
        since += b - a
        if since >= points_per_step:
            since = 0
            yield b / total


def point_cloud_from_arrays(name, xyz):
    """A mesh of loose vertices at `xyz` ((n, 3) floats: IFS point sets)."""
    mesh = bpy.data.meshes.new(name)
    xyz = np.ascontiguousarray(xyz, dtype=np.float32).ravel()
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


def curve_polylines(obj, matrix, shift=(0.0, 0.0, 0.0), radius_scale=None):
    """A core.Polylines of a curve object's splines of 2 or more points, each point
    mapped by the 4x4 `matrix` then moved by `shift`, with radius times the bevel
    depth (or times `radius_scale`: a bevel object's half-width); None when no
    spline has 2 points."""
    m = np.array(matrix, dtype=np.float64)
    depth = max(obj.data.bevel_depth, 0.0) if radius_scale is None else radius_scale
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
