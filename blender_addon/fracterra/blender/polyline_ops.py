"""Curves: Add > Curve > Fractal Polyline, coastlines of a terrain, and measures."""

import array
import math

import bpy
from mathutils import Matrix

from .. import core
from ..core import params
from . import props
from .terrain_build import SettingsError, WindowProgress

REPORTED = (core.FracterraError, SettingsError)


def edge_chain(mesh):
    """Vertex indices of a mesh that is one chain of edges (open or closed), in order."""
    n = len(mesh.vertices)
    adjacent = [[] for _ in range(n)]
    for e in mesh.edges:
        a, b = e.vertices
        adjacent[a].append(b)
        adjacent[b].append(a)
    used = [v for v in range(n) if adjacent[v]]
    if len(used) < 2 or any(len(adjacent[v]) > 2 for v in used):
        raise SettingsError(f"the active mesh '{mesh.name}' must be a single chain of edges (every vertex on at most "
                            "two edges), e.g. a converted curve or extruded vertices")
    ends = [v for v in used if len(adjacent[v]) == 1]
    chain, prev = [ends[0] if ends else used[0]], None
    while True:
        nxt = [v for v in adjacent[chain[-1]] if v != prev and (v != chain[0] or not ends)]
        if not nxt or nxt[0] == chain[0]:
            if nxt:  # closed loop: repeat the first vertex
                chain.append(chain[0])
            break
        prev = chain[-1]
        chain.append(nxt[0])
    if len(set(chain)) != len(used):
        raise SettingsError(f"the active mesh '{mesh.name}' has more than one edge chain")
    return chain


def base_polyline(values, context):
    """(points, matrix): the base nodes in the frame of `matrix` (the new object's)."""
    if values["base_source"] == "POINTS":
        start, end = values["start"], values["end"]
        if start == end:
            raise SettingsError("Start and End are the same point; move one of them")
        return [start, end], Matrix.Identity(4)
    obj = context.active_object
    if obj is None or obj.type not in {"CURVE", "MESH"}:
        raise SettingsError("Base 'Active Object' needs an active curve or mesh (edge chain)")
    if obj.type == "CURVE":
        if not obj.data.splines:
            raise SettingsError(f"the active curve '{obj.name}' has no splines")
        spline = obj.data.splines[0]
        pts = spline.bezier_points if spline.type == "BEZIER" else spline.points
        nodes = [tuple(p.co[:3]) for p in pts]
        if spline.use_cyclic_u and nodes:
            nodes.append(nodes[0])
    else:
        co = obj.data.vertices
        nodes = [tuple(co[i].co) for i in edge_chain(obj.data)]
    if len(nodes) < 2:
        raise SettingsError(f"the active object '{obj.name}' gives fewer than 2 base points")
    return nodes, obj.matrix_world.copy()


def curve_from_polylines(name, pl, bevel, z_offset=0.0, transform=None):
    """A new curve datablock with one POLY spline per line, radii from the library."""
    curve = bpy.data.curves.new(name, "CURVE")
    curve.dimensions = "3D"
    if bevel:
        curve.bevel_depth = 1.0  # times each point's radius
        curve.bevel_resolution = 2
        curve.use_fill_caps = True
    xyz, radii, offsets = pl.xyz(), pl.radii(), pl.offsets()
    for k in range(len(offsets) - 1):
        a, b = offsets[k], offsets[k + 1]
        if b - a < 2:
            continue
        spline = curve.splines.new("POLY")
        spline.points.add(b - a - 1)
        co = array.array("f", [0.0]) * (4 * (b - a))
        for i in range(a, b):
            x, y, z = xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2] + z_offset
            if transform:
                x, y, z = transform(x, y, z)
            j = 4 * (i - a)
            co[j], co[j + 1], co[j + 2], co[j + 3] = x, y, z, 1.0
        spline.points.foreach_set("co", co)
        spline.points.foreach_set("radius", array.array("f", radii[a:b]))
    return curve


def point_cloud_from_polylines(name, pl):
    mesh = bpy.data.meshes.new(name)
    xyz = pl.xyz()
    mesh.vertices.add(len(xyz) // 3)
    mesh.vertices.foreach_set("co", array.array("f", xyz))
    mesh.update()
    return mesh


def link_new_object(context, name, data, matrix):
    obj = bpy.data.objects.new(name, data)
    obj.matrix_world = matrix
    context.collection.objects.link(obj)
    for other in context.selected_objects:
        other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
    return obj


class FRACTERRA_OT_polyline_add(bpy.types.Operator):
    """Add a fractal polyline (FPL 2D/3D with branching, Koch, dragon, Sierpinski, IFS, profile)"""
    bl_idname = "curve.fracterra_polyline_add"
    bl_label = "Fractal Polyline"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    def draw(self, context):
        props.draw_polyline_settings(self.layout, self)

    def execute(self, context):
        values = params.values_of(self, params.POLYLINE_PARAMS)
        try:
            from .panels import preferences
            prefs = preferences(context)
            base, matrix = base_polyline(values, context)
            with WindowProgress(context) as progress, \
                    core.generate_polylines(values, base=base, progress=progress,
                                            threads=prefs.threads if prefs else 0) as pl:
                if values["method"] == "IFS":
                    data = point_cloud_from_polylines("Fractal Points", pl)
                else:
                    data = curve_from_polylines("Fractal Polyline", pl, values["bevel"])
                lines, vertices = pl.line_count, pl.vertex_count
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        obj = link_new_object(context, data.name, data, matrix)
        # How exporters should show it (POV-Ray: glowing lightning or a plain tube).
        obj["fracterra_kind"] = "LIGHTNING" if values["method"] == "FPL3D" else "LINE"
        self.report({"INFO"}, f"Fractal polyline: {lines} line(s), {vertices} vertices")
        return {"FINISHED"}


FRACTERRA_OT_polyline_add.__annotations__ = props.terrain_annotations(param_list=params.POLYLINE_PARAMS)


def terrain_grid_size(obj):
    """(nx, ny) of a fracterra terrain object whose mesh is still its grid."""
    s = obj.fracterra_terrain
    nx, ny = ((2 ** s.levels + 1,) * 2 if s.method in params.DYADIC_METHODS else (s.width, s.height))
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


def is_terrain(obj):
    return obj is not None and obj.type == "MESH" and obj.fracterra_terrain.is_terrain


class FRACTERRA_OT_coastline_add(bpy.types.Operator):
    """Add the coastline (level set) of the active fractal terrain as a curve"""
    bl_idname = "curve.fracterra_coastline_add"
    bl_label = "Terrain Coastline"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    use_quantile: bpy.props.BoolProperty(
        name="By Quantile", default=True,
        description="Level as the fraction of the terrain below it (0.5: half is sea); off: a height")
    quantile: bpy.props.FloatProperty(name="Quantile", default=0.5, min=0.0, max=1.0, subtype="FACTOR",
                                      description="Fraction of the terrain below the coastline")
    level: bpy.props.FloatProperty(name="Level", default=0.0, subtype="DISTANCE", unit="LENGTH",
                                   description="Height of the coastline (local z)")
    radius: bpy.props.FloatProperty(name="Radius", default=0.02, min=0.0, subtype="DISTANCE", unit="LENGTH",
                                    description="Bevel radius of the coastline curve (0: a bare line)")

    @classmethod
    def poll(cls, context):
        return is_terrain(context.active_object) and context.mode == "OBJECT"

    def execute(self, context):
        terrain = context.active_object
        try:
            with heightfield_of(terrain) as hf:
                nx, ny = hf.width, hf.height
                size_x, size_y = core.grid_size(terrain.fracterra_terrain.world_size, nx, ny)
                level = self.quantile if self.use_quantile else self.level
                with core.coastline(hf, level, quantile=self.use_quantile) as pl:
                    if pl.line_count == 0:
                        # Not an empty curve without a word: say why.
                        s = hf.stats()
                        what = f"quantile {level:g}" if self.use_quantile else f"level {level:g}"
                        self.report({"ERROR"}, f"no coastline at {what}: the terrain's heights are "
                                               f"[{s['min']:g}, {s['max']:g}] and no cell crosses it")
                        return {"CANCELLED"}
                    def to_local(x, y, z):
                        return (x / (nx - 1) - 0.5) * size_x, (y / (ny - 1) - 0.5) * size_y, z
                    curve = curve_from_polylines("Coastline", pl, bevel=False, transform=to_local)
                    lines = pl.line_count
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        if self.radius > 0:
            curve.bevel_depth = self.radius
        obj = link_new_object(context, f"{terrain.name} Coastline", curve, terrain.matrix_world.copy())
        obj.parent = terrain
        obj.matrix_parent_inverse = terrain.matrix_world.inverted()
        obj["fracterra_kind"] = "COASTLINE"
        self.report({"INFO"}, f"Coastline: {lines} line(s)")
        return {"FINISHED"}


def polylines_of_curve(obj, matrix=None):
    """A core.Polylines of a curve object's splines (world coordinates unless `matrix`)."""
    m = matrix if matrix is not None else obj.matrix_world
    lines, radii = [], []
    for spline in obj.data.splines:
        pts = spline.bezier_points if spline.type == "BEZIER" else spline.points
        if len(pts) >= 2:
            lines.append([tuple(m @ p.co.to_3d()) for p in pts])
            radii.append([p.radius * max(obj.data.bevel_depth, 0.0) for p in pts])
    if not lines:
        raise SettingsError(f"the curve '{obj.name}' has no spline with 2 or more points")
    return core.Polylines.from_lines(lines, radii)


class FRACTERRA_OT_measure(bpy.types.Operator):
    """Measure the active terrain (H, D) or curve (eta, chi, gamma, box-counting D)"""
    bl_idname = "object.fracterra_measure"
    bl_label = "Measure"
    bl_options = {"REGISTER"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and (is_terrain(obj) or obj.type == "CURVE")

    def execute(self, context):
        obj = context.active_object
        m = obj.fracterra_measures
        try:
            if obj.type == "CURVE":
                with polylines_of_curve(obj, Matrix.Identity(4)) as pl:
                    s = pl.measure()
                m.kind, m.eta, m.chi, m.gamma = "polylines", s["eta"], s["chi"], s["gamma"]
                m.dimension, m.stderr, m.hurst = s["box_dimension"], s["box_std_error"], math.nan
            else:
                with heightfield_of(obj) as hf:
                    r = core.hurst_of_heightfield(hf)  # the library's recommended estimator, as the CLI's
                m.kind, m.hurst, m.dimension, m.stderr = "terrain", r["hurst"], r["dimension"], r["stderr_hurst"]
                m.estimator, m.estimator_reason = r["estimator"], r["reason"]
                m.eta = m.chi = m.gamma = math.nan
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class FRACTERRA_PT_measures(bpy.types.Panel):
    bl_label = "Fractal Measures"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Fracterra"

    @classmethod
    def poll(cls, context):
        return FRACTERRA_OT_measure.poll(context)

    def draw(self, context):
        layout = self.layout
        obj = context.active_object
        m = obj.fracterra_measures
        layout.operator(FRACTERRA_OT_measure.bl_idname, icon="DRIVER_DISTANCE")
        if not m.kind:
            layout.label(text="Not measured yet")
            return
        col = layout.column(align=True)
        if m.kind == "terrain" and m.estimator:
            col.label(text=f"Estimator: {m.estimator}")
        names = ("hurst", "dimension", "stderr") if m.kind == "terrain" else ("eta", "chi", "gamma", "dimension", "stderr")
        for name in names:
            row = col.row()
            row.label(text=m.bl_rna.properties[name].name)
            value = getattr(m, name)
            row.label(text="n/a" if math.isnan(value) else f"{value:.4f}")


def menu_curve_add(self, context):
    self.layout.operator(FRACTERRA_OT_polyline_add.bl_idname, text="Fractal Polyline", icon="IPO_ELASTIC")
    self.layout.operator(FRACTERRA_OT_coastline_add.bl_idname, text="Terrain Coastline", icon="MOD_OCEAN")
