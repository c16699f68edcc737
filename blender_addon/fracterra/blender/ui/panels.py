"""The sidebar panels (View3D > Sidebar > Fracterra). They refer to operators by
their id strings, so no panel imports an operator module."""

import math

import bpy

from .settings_layout import draw_polyline_settings, draw_settings
from .planet_layout import draw_planet_settings
from ..build.planet import planet_of
from ..build.objects import geometry_fingerprint, is_measurable, is_polyline, mesh_level
from ..build.water import terrain_of
from ...core import params
from ...core.params import grid_shape
from ..common.widgets import draw_library_problem, draw_size, draw_wrapped

# Operators the panels show (bl_idname of each).
TERRAIN_ADD = "mesh.fracterra_terrain_add"
TERRAIN_REGENERATE = "object.fracterra_terrain_regenerate"
POLYLINE_REGENERATE = "object.fracterra_polyline_regenerate"
PLANET_ADD = "mesh.fracterra_planet_add"
PLANET_REGENERATE = "object.fracterra_planet_regenerate"
MEASURE = "object.fracterra_measure"


def draw_regenerate(layout, settings, operator, text="Regenerate"):
    """Regenerate (operator `operator`), Auto Update and the last error of a
    terrain's or a polyline's settings, at the top of its panel."""
    # One button a row: side by side the sidebar cuts their labels.
    col = layout.column(align=True)
    col.operator(operator, text=text, icon="FILE_REFRESH")
    col.prop(settings, "auto_update", toggle=True)
    if settings.last_error:
        draw_wrapped(layout, settings.last_error, icon="ERROR", alert=True, width=32)


def draw_mesh_level(layout, settings, level):
    """Which level the mesh holds: Preview (Auto Update's) or Final (Levels)."""
    col = layout.column(align=True)
    if level is None:
        col.label(text="Mesh: edited, not its grid", icon="ERROR")
        return
    kind, nx, ny = level
    col.label(text=f"Mesh: {kind}, {nx} x {ny}", icon="MESH_GRID")
    if kind == "Preview":
        fx, fy = grid_shape(params.values_of(settings))
        col.label(text=f"Final: {fx} x {fy}", icon="RENDER_STILL")


class _SidebarPanel:
    """Where every panel of the add-on stands: View3D > Sidebar > Fracterra;
    shown when the active object is one `shows(obj)` accepts."""
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Fracterra"

    @classmethod
    def poll(cls, context):
        return cls.shows(context.active_object)


class FRACTERRA_PT_terrain(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Terrain"

    @staticmethod
    def shows(obj):
        return not is_polyline(obj) and planet_of(obj) is None  # polylines and planets have their own

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        # A terrain, or one of its water objects or its coastline: the terrain's settings.
        obj = terrain_of(context.active_object)
        settings = obj.fracterra_terrain if obj is not None else None
        if settings is None:
            draw_wrapped(layout, "The active object is not a fractal terrain.", width=32)
            col = layout.column(align=True)
            col.operator(TERRAIN_ADD, text="Add Fractal Terrain", icon="RNDCURVE")
            col.operator(PLANET_ADD, text="Add Fractal Planet", icon="MESH_UVSPHERE")
            return
        if obj != context.active_object:
            layout.label(text=f"Terrain: {obj.name}", icon="MESH_GRID")
        level = mesh_level(obj)
        draw_regenerate(layout, settings, TERRAIN_REGENERATE,
                        text="Build Final" if level is not None and level[0] == "Preview" else "Regenerate")
        draw_mesh_level(layout, settings, level)
        draw_settings(layout, settings, compact=True)
        draw_size(layout, params.values_of(settings))


class FRACTERRA_PT_planet(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Planet"

    @staticmethod
    def shows(obj):
        return planet_of(obj) is not None

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        # The planet, or its sea sphere: the planet's settings.
        obj = planet_of(context.active_object)
        settings = obj.fracterra_planet
        if obj != context.active_object:
            layout.label(text=f"Planet: {obj.name}", icon="MESH_UVSPHERE")
        level = mesh_level(obj)
        draw_regenerate(layout, settings, PLANET_REGENERATE,
                        text="Build Final" if level is not None and level[0] == "Preview" else "Regenerate")
        col = layout.column(align=True)
        if level is None:
            col.label(text="Mesh: edited, not its cube-sphere", icon="ERROR")
        else:
            kind = "" if level[0] == "Other" else f"{level[0]}, "
            col.label(text=f"Mesh: {kind}level {level[1]}", icon="MESH_UVSPHERE")
            if level[0] != "Final":
                col.label(text=f"Regenerate builds level {settings.level}", icon="RENDER_STILL")
        draw_planet_settings(layout, settings, compact=True)


class FRACTERRA_PT_polyline(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Polyline"
    shows = staticmethod(is_polyline)

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        settings = context.active_object.fracterra_polyline
        draw_regenerate(layout, settings, POLYLINE_REGENERATE)
        draw_polyline_settings(layout, settings, compact=True)


class FRACTERRA_PT_measures(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Measures"
    shows = staticmethod(is_measurable)

    def draw(self, context):
        layout = self.layout
        obj = context.active_object
        m = obj.fracterra_measures
        layout.operator(MEASURE, icon="DRIVER_DISTANCE")
        if not m.kind:
            layout.label(text="Not measured yet")
            return
        col = layout.column(align=True)
        if m.geometry != geometry_fingerprint(obj):
            # Measured before the last change (Regenerate, an edit): never shown as current.
            draw_wrapped(layout, "Stale: the object changed since it was measured; press Measure again",
                         icon="ERROR", alert=True)
            col.enabled = False
        if m.kind == "terrain" and m.estimator:
            col.label(text=f"Estimator: {m.estimator}")
        names = ("hurst", "dimension", "std_error") if m.kind == "terrain" else ("eta", "chi", "gamma", "dimension", "std_error")
        for name in names:
            row = col.row()
            row.label(text=m.bl_rna.properties[name].name)
            value = getattr(m, name)
            row.label(text="n/a" if math.isnan(value) else f"{value:.4f}")
