# SPDX-License-Identifier: GPL-3.0-or-later
"""Curves: Add > Curve > Fractal Polyline, and the coastlines of a terrain."""

import json

import bpy
import numpy as np
from bpy_extras import object_utils
from mathutils import Matrix

from ... import core
from ...core import params
from ..ui import properties as props
from ..build.curve import link_new_object, spline_nodes
from ..build.polyline import default_radius, polyline_job, regenerate_job
from ..build.strike import strike_base
from ..common.jobs import Job, JobOperator
from ..common.reporting import SettingsError
from ..common.widgets import draw_placement
from ..ui.settings_layout import draw_polyline_settings
from ..build import children, coastline
from ..build.objects import active_object, heightfield_of, is_polyline, sea_height_of
from ..build.water import terrain_of


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
        nodes = [tuple(p) for p in spline_nodes(spline)]
        if spline.use_cyclic_u and nodes:
            nodes.append(nodes[0])
    else:
        co = obj.data.vertices
        nodes = [tuple(co[i].co) for i in edge_chain(obj.data)]
    if len(nodes) < 2:
        raise SettingsError(f"the active object '{obj.name}' gives fewer than 2 base points")
    return nodes, obj.matrix_world.copy()


class FRACTERRA_OT_polyline_add(JobOperator, bpy.types.Operator, object_utils.AddObjectHelper):
    """Add a fractal polyline (FPL 2D/3D with branching, Koch, dragon, Sierpinski, IFS, profile) at the 3D cursor"""
    bl_idname = "curve.fracterra_polyline_add"
    bl_label = "Fractal Polyline"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    def draw(self, context):
        draw_polyline_settings(self.layout, self)
        if self.base_source == "POINTS":
            draw_placement(self.layout, self)

    def fill_base(self, context):
        """Start, End and Radius from the method's own defaults (METHOD_BASES)
        unless the caller gave them or they were edited by hand: a Koch curve
        chosen after a bolt lies flat, not on the bolt's vertical. The default
        bolt over a terrain strikes its surface under the 3D cursor. What was
        filled in is kept in `filled` (JSON) to tell it from an edit."""
        is_set = self.properties.is_property_set
        method = self.method
        record = json.loads(self.filled) if self.filled else None
        if record is None and (is_set("start") or is_set("end")):
            return None  # the caller's own points
        now = [list(self.start), list(self.end), self.radius]
        if record is not None and (now != record["base"] or record["method"] == method):
            return record["struck"] if now == record["base"] else None  # kept, or edited by hand
        start, end = METHOD_BASES.get(method, FLAT_BASE)
        struck = None
        if method == "FPL3D":
            start, end, terrain = strike_base(context, object_utils.add_object_align_init(context, self), start, end)
            struck = terrain.name if terrain is not None else None
        self.start, self.end = start, end
        if record is not None or not is_set("radius"):
            self.radius = default_radius([start, end])
        self.filled = json.dumps({"method": method, "struck": struck,
                                  "base": [list(self.start), list(self.end), self.radius]})
        return struck

    # From the menu it runs in the background with a progress bar (Esc cancels);
    # the redo panel and scripts run execute() (progress.JobOperator).
    def make_job(self, context):
        self._struck = self.fill_base(context) if self.base_source == "POINTS" else None
        values = params.values_of(self, params.POLYLINE_PARAMS)
        base, self._matrix = base_polyline(values, context)
        if not self.properties.is_property_set("radius"):
            self.radius = values["radius"] = default_radius(base)
        self._base = base
        return polyline_job(values, base, context)

    def job_done(self, context, value):
        data, summary = value
        values = params.values_of(self, params.POLYLINE_PARAMS)
        if values["base_source"] == "POINTS":
            # At the 3D cursor (or Location), aligned as asked, like Blender's own primitives.
            obj = object_utils.object_data_add(context, data, operator=self)
        else:
            obj = link_new_object(context, data.name, data, self._matrix)
        settings = obj.fracterra_polyline
        props.copy_settings(self, settings, params.POLYLINE_PARAMS)
        settings.base_nodes = json.dumps([list(p) for p in self._base]) if values["base_source"] == "ACTIVE" else ""
        settings.is_polyline = True
        # How exporters should show it (POV-Ray: glowing lightning or a plain tube).
        obj["fracterra_kind"] = "LIGHTNING" if values["method"] == "FPL3D" else "LINE"
        terrain = bpy.data.objects.get(self._struck) if self._struck else None
        if terrain is not None:
            # A child of the terrain it struck: aimed again when the terrain re-generates.
            world = obj.matrix_world.copy()
            obj.parent = terrain
            obj.matrix_parent_inverse = terrain.matrix_world.inverted()
            obj.matrix_world = world
            children.remember_strike(obj)
        self.report({"INFO"}, f"Fractal polyline: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}


# Each method's own base when the caller gives none: the bolt falls from 10 m
# onto the 3D cursor; the plane curves (Koch, dragon, ...) and the profile lie
# flat along x, 10 m long, centred on it (on a vertical base they show edge-on, a bar).
METHOD_BASES = {"FPL3D": ((0.0, 0.0, 10.0), (0.0, 0.0, 0.0))}
FLAT_BASE = ((-5.0, 0.0, 0.0), (5.0, 0.0, 0.0))


# A new Add starts from its method's base and radius, never the last Add's (SKIP_SAVE).
FRACTERRA_OT_polyline_add.__annotations__ = {
    **props.terrain_annotations(param_list=params.POLYLINE_PARAMS),
    **props.terrain_annotations(param_list=[p for p in params.POLYLINE_PARAMS if p.name in ("start", "end", "radius")],
                                options={"SKIP_SAVE"}),
    "filled": bpy.props.StringProperty(name="Filled", default="", options={"HIDDEN", "SKIP_SAVE"},
                                       description="The method whose own base fills Start, End and Radius (JSON)"),
}


class FRACTERRA_OT_polyline_regenerate(JobOperator, bpy.types.Operator):
    """Regenerate the active fractal polyline from its settings, in place"""
    bl_idname = "object.fracterra_polyline_regenerate"
    bl_label = "Regenerate Polyline"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return is_polyline(active_object(context)) and context.mode == "OBJECT"

    def make_job(self, context):
        self._obj = active_object(context)
        self._obj.fracterra_polyline.last_error = ""
        return regenerate_job(self._obj, context)

    def _refuse(self, e):
        obj = active_object(bpy.context)
        if is_polyline(obj):
            obj.fracterra_polyline.last_error = str(e)
        return super()._refuse(e)

    def job_done(self, context, summary):
        obj = self._obj
        obj["fracterra_kind"] = "LIGHTNING" if obj.fracterra_polyline.method == "FPL3D" else "LINE"
        self.report({"INFO"}, f"Fractal polyline: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}


# Why Terrain Coastline is greyed out, shown in its tooltip.
COASTLINE_NEEDS = "Select a fractal terrain (Add > Mesh > Fractal Terrain) in Object Mode to draw its coastline"


def coastline_terrain(obj):
    """The terrain a coastline is drawn for: the active terrain, or the terrain
    of the active coastline or water object (what is active right after the
    operator, when its redo panel re-runs it)."""
    return terrain_of(obj)


class FRACTERRA_OT_coastline_add(JobOperator, bpy.types.Operator):
    """Add the coastline (level set) of the active fractal terrain as a curve"""
    bl_idname = "curve.fracterra_coastline_add"
    bl_label = "Terrain Coastline"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    use_quantile: bpy.props.BoolProperty(
        name="By Quantile", default=True,
        description="Level as the fraction of the ground below it (0.5: half is sea); on a terrain with a "
                    "flat sea, the fraction of the land above that sea; off: a height")
    quantile: bpy.props.FloatProperty(name="Quantile", default=0.5, min=0.0, max=1.0, subtype="FACTOR",
                                      description="Fraction of the ground below the coastline; with a flat sea, "
                                                  "of the land above it (0: the shore)")
    level: bpy.props.FloatProperty(name="Level", default=0.0, subtype="DISTANCE", unit="LENGTH",
                                   description="Height of the coastline (local z); at a terrain's flat sea it "
                                               "is taken just above it")
    radius: bpy.props.FloatProperty(name="Radius", default=0.0, min=0.0, soft_max=1.0, subtype="DISTANCE",
                                    unit="LENGTH", description="Radius of the coastline's tube (0: a bare line); "
                                                               "when not given, 1/500 of the terrain's size")

    @classmethod
    def poll(cls, context):
        if context.mode == "OBJECT" and coastline_terrain(active_object(context)) is not None:
            return True
        cls.poll_message_set(COASTLINE_NEEDS)
        return False

    def request(self, settings, hf):
        """What the coastline is traced for: the operator's level, or what the
        caller left unset from the terrain: its sea when it has one (the level
        then follows the sea when the terrain re-generates)."""
        is_set = self.properties.is_property_set
        from_sea = settings.sea != "NONE" and not (is_set("use_quantile") or is_set("quantile") or is_set("level"))
        if from_sea:
            self.use_quantile = False
            self.level = sea_height_of(settings.sea, settings.sea_level, float(np.frombuffer(hf.to_array(), dtype=np.float32).min()))
        if not is_set("radius"):
            self.radius = settings.world_size / 500
        return {"use_quantile": self.use_quantile, "quantile": self.quantile, "level": self.level,
                "level_from_sea": from_sea, "sea": settings.sea, "sea_level": settings.sea_level}

    def make_job(self, context):
        terrain = coastline_terrain(active_object(context))
        settings = terrain.fracterra_terrain
        hf = heightfield_of(terrain)  # read here (it needs bpy); freed by the work
        try:
            nx, ny = hf.width, hf.height
            request = self.request(settings, hf)
        except BaseException:
            hf.close()
            raise

        def work(progress):
            with hf:
                return coastline.trace(hf, request)

        transform = coastline.to_local(nx, ny, core.grid_size(settings.world_size, nx, ny))

        def build(lines):
            curve = yield from coastline.build_curve(lines, self.radius, transform)
            return curve, lines.line_count

        self._terrain, self._request = terrain, request
        return Job("Tracing coastline", work, build, work_share=0.3)

    def job_done(self, context, value):
        curve, lines = value
        terrain = self._terrain
        obj = link_new_object(context, f"{terrain.name} Coastline", curve, terrain.matrix_world.copy())
        obj.parent = terrain
        obj.matrix_parent_inverse = terrain.matrix_world.inverted()
        obj["fracterra_kind"] = coastline.KIND
        coastline.remember(obj, self._request, self.radius)
        self.report({"INFO"}, f"Coastline: {lines} line(s)")
        return {"FINISHED"}
