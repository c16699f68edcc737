"""Curves: Add > Curve > Fractal Polyline, and the coastlines of a terrain."""

import json

import bpy
import numpy as np
from bpy_extras import object_utils
from mathutils import Matrix

from ... import core
from ...core import params
from ..ui import properties as props
from ..build.curve import LineArrays, fill_curve_steps, link_new_object, new_curve, spline_nodes
from ..build.polyline import default_radius, polyline_job, regenerate_job
from ..common.jobs import Job, JobOperator
from ..common.reporting import SettingsError
from ..common.widgets import draw_placement
from ..ui.settings_layout import draw_polyline_settings
from ..build.objects import heightfield_of, is_polyline, is_terrain, sea_height


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

    # From the menu it runs in the background with a progress bar (Esc cancels);
    # the redo panel and scripts run execute() (progress.JobOperator).
    def make_job(self, context):
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
        self.report({"INFO"}, f"Fractal polyline: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}


FRACTERRA_OT_polyline_add.__annotations__ = props.terrain_annotations(param_list=params.POLYLINE_PARAMS)


class FRACTERRA_OT_polyline_regenerate(JobOperator, bpy.types.Operator):
    """Regenerate the active fractal polyline from its settings, in place"""
    bl_idname = "object.fracterra_polyline_regenerate"
    bl_label = "Regenerate Polyline"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return is_polyline(context.active_object) and context.mode == "OBJECT"

    def make_job(self, context):
        self._obj = context.active_object
        self._obj.fracterra_polyline.last_error = ""
        return regenerate_job(self._obj, context)

    def _refuse(self, e):
        obj = bpy.context.active_object
        if is_polyline(obj):
            obj.fracterra_polyline.last_error = str(e)
        return super()._refuse(e)

    def job_done(self, context, summary):
        obj = self._obj
        obj["fracterra_kind"] = "LIGHTNING" if obj.fracterra_polyline.method == "FPL3D" else "LINE"
        self.report({"INFO"}, f"Fractal polyline: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}


def land_quantile(hf, sea, q):
    """The height with the fraction `q` of the land (heights above the flat sea
    at `sea`) below it. The flat sea is left out: when it covers more than half
    the map, a quantile of all heights would fall on it and find no coast."""
    z = np.frombuffer(hf.to_array(), dtype=np.float32)
    land = np.sort(z[z > sea])
    if land.size == 0:
        raise SettingsError(f"no land above the sea at {sea:g}: the whole terrain is sea; lower its Sea Level")
    return float(land[min(land.size - 1, int(q * land.size))])


# Why Terrain Coastline is greyed out, shown in its tooltip.
COASTLINE_NEEDS = "Select a fractal terrain (Add > Mesh > Fractal Terrain) in Object Mode to draw its coastline"


def coastline_terrain(obj):
    """The terrain a coastline is drawn for: the active terrain, or the parent of
    the active coastline (what is active right after the operator, when its redo
    panel re-runs it)."""
    if is_terrain(obj):
        return obj
    if obj is not None and obj.get("fracterra_kind") == "COASTLINE" and is_terrain(obj.parent):
        return obj.parent
    return None


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
        if context.mode == "OBJECT" and coastline_terrain(context.active_object) is not None:
            return True
        cls.poll_message_set(COASTLINE_NEEDS)
        return False

    def defaults_from(self, settings, sea):
        """What the caller left unset comes from the terrain: its sea (height
        `sea`, None without one) when it has one, and a tube visible at its size."""
        is_set = self.properties.is_property_set
        if sea is not None and not (is_set("use_quantile") or is_set("quantile") or is_set("level")):
            self.use_quantile, self.level = False, sea
        if not is_set("radius"):
            self.radius = settings.world_size / 500

    def make_job(self, context):
        terrain = coastline_terrain(context.active_object)
        settings = terrain.fracterra_terrain
        hf = heightfield_of(terrain)  # read here (it needs bpy); freed by the work
        try:
            nx, ny = hf.width, hf.height
            world_size_x, world_size_y = core.grid_size(settings.world_size, nx, ny)
            s = hf.stats()
            sea = sea_height(settings, s["min"])
            self.defaults_from(settings, sea)
            level = self.quantile if self.use_quantile else self.level
            by_quantile = self.use_quantile
            if by_quantile and sea is not None:
                level = land_quantile(hf, sea, self.quantile)
                by_quantile = False
            if not by_quantile and sea is not None and level <= sea:
                # The flattened sea lies exactly at the sea level and counts as land
                # there (land: height >= level): take the level just above it.
                level = sea + 1e-5 * max(s["max"] - s["min"], 1e-6)
        except BaseException:
            hf.close()
            raise

        def work(progress):
            with hf, core.coastline(hf, level, quantile=by_quantile) as pl:
                if pl.line_count == 0:
                    # Not an empty curve without a word: say why.
                    what = f"quantile {level:g}" if by_quantile else f"level {level:g}"
                    raise SettingsError(f"no coastline at {what}: the terrain's heights are "
                                        f"[{s['min']:g}, {s['max']:g}] and no cell crosses it")
                return LineArrays(pl, unit_radius=True)

        def to_local(x, y, z):
            return (x / (nx - 1) - 0.5) * world_size_x, (y / (ny - 1) - 0.5) * world_size_y, z

        def build(lines):
            curve = new_curve("Coastline", bevel=False)
            try:
                yield from fill_curve_steps(curve, lines, transform=to_local)
            except BaseException:  # GeneratorExit too: a cancel leaves no curve behind
                bpy.data.curves.remove(curve)
                raise
            curve.bevel_depth = self.radius  # times each point's radius of 1
            return curve, lines.line_count

        self._terrain = terrain
        return Job("Tracing coastline", work, build, work_share=0.3)

    def job_done(self, context, value):
        curve, lines = value
        terrain = self._terrain
        obj = link_new_object(context, f"{terrain.name} Coastline", curve, terrain.matrix_world.copy())
        obj.parent = terrain
        obj.matrix_parent_inverse = terrain.matrix_world.inverted()
        obj["fracterra_kind"] = "COASTLINE"
        self.report({"INFO"}, f"Coastline: {lines} line(s)")
        return {"FINISHED"}
