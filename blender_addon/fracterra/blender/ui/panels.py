# SPDX-License-Identifier: GPL-3.0-or-later
"""The sidebar panels (View3D > Sidebar > Fracterra). They refer to operators by
their id strings, so no panel imports an operator module."""

import math

import bpy

from .settings_layout import draw_polyline_settings, draw_settings
from .planet_layout import draw_planet_settings
from ..build.planet import planet_of
from ..build import kept_final
from ..build.objects import (active_object, built_settings, geometry_fingerprint, is_measurable, is_polyline,
                             mesh_level, out_of_date)
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
BACK_TO_FINAL = "object.fracterra_back_to_final"


def draw_regenerate(layout, settings, operator, text="Regenerate"):
    """Regenerate (operator `operator`), Auto Update and the last error of a
    terrain's or a polyline's settings, at the top of its panel."""
    # One button a row: side by side the sidebar cuts their labels.
    col = layout.column(align=True)
    col.operator(operator, text=text, icon="FILE_REFRESH")
    col.prop(settings, "auto_update", toggle=True)
    if settings.last_error:
        draw_wrapped(layout, settings.last_error, icon="ERROR", alert=True)


def draw_out_of_date(layout, stale):
    """Which settings the mesh was not built from (objects.out_of_date), alert."""
    if stale:
        names = ", ".join(stale[:3]) + (f" and {len(stale) - 3} more" if len(stale) > 3 else "")
        draw_wrapped(layout, f"Out of date: {names} changed", icon="ERROR", alert=True)


def draw_mesh_level(layout, obj, settings, level, stale):
    """Which level the mesh holds: Preview (Auto Update's) or Final (Levels),
    whether it is out of date, and the Final kept beside a Preview."""
    col = layout.column(align=True)
    if level is None:
        col.label(text="Mesh: edited, not its grid", icon="ERROR")
        return
    kind, nx, ny = level
    col.label(text=f"Mesh: {kind}, {nx} x {ny}", icon="MESH_GRID")
    draw_out_of_date(col, stale)
    if kind == "Preview":
        fx, fy = grid_shape(params.values_of(settings))
        kept = kept_final.kept(obj)
        if kept is not None:
            kx, ky = grid_shape(built_settings(kept) or params.values_of(settings))
            col.label(text=f"Final: {kx} x {ky}, kept", icon="RENDER_STILL")
            draw_out_of_date(col, out_of_date(obj, kept))
            col.operator(BACK_TO_FINAL, icon="LOOP_BACK")
        else:
            col.label(text=f"Final: {fx} x {fy}", icon="RENDER_STILL")


def build_label(level, stale):
    """The top button: Build Final where the mesh is a Preview or out of date."""
    return "Build Final" if level is not None and (level[0] == "Preview" or stale) else "Regenerate"


class _SidebarPanel:
    """Where every panel of the add-on stands: View3D > Sidebar > Fracterra;
    shown when the active object is one `shows(obj)` accepts."""
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Fracterra"

    @classmethod
    def poll(cls, context):
        return cls.shows(active_object(context))


class FRACTERRA_PT_terrain(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Terrain"

    @staticmethod
    def shows(obj):
        return not is_polyline(obj) and planet_of(obj) is None  # polylines and planets have their own

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        # A terrain, or one of its water objects or its coastline: the terrain's settings.
        active = active_object(context)
        obj = terrain_of(active)
        settings = obj.fracterra_terrain if obj is not None else None
        if settings is None:
            draw_wrapped(layout, "The active object is not a fractal terrain.")
            col = layout.column(align=True)
            col.operator(TERRAIN_ADD, text="Add Fractal Terrain", icon="RNDCURVE")
            col.operator(PLANET_ADD, text="Add Fractal Planet", icon="MESH_UVSPHERE")
            return
        if obj != active:
            layout.label(text=f"Terrain: {obj.name}", icon="MESH_GRID")
        if not obj.visible_get():
            layout.label(text="Hidden (with its water)", icon="HIDE_ON")
        level, stale = mesh_level(obj), out_of_date(obj)
        draw_regenerate(layout, settings, TERRAIN_REGENERATE, text=build_label(level, stale))
        draw_mesh_level(layout, obj, settings, level, stale)
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
        active = active_object(context)
        obj = planet_of(active)
        settings = obj.fracterra_planet
        if obj != active:
            layout.label(text=f"Planet: {obj.name}", icon="MESH_UVSPHERE")
        level, stale = mesh_level(obj), out_of_date(obj)
        draw_regenerate(layout, settings, PLANET_REGENERATE, text=build_label(level, stale))
        col = layout.column(align=True)
        if level is None:
            col.label(text="Mesh: edited, not its cube-sphere", icon="ERROR")
        else:
            kind = "" if level[0] == "Other" else f"{level[0]}, "
            col.label(text=f"Mesh: {kind}level {level[1]}", icon="MESH_UVSPHERE")
            draw_out_of_date(col, stale)
            if level[0] != "Final":
                col.label(text=f"Build Final: level {settings.level}", icon="RENDER_STILL")
        draw_planet_settings(layout, settings, compact=True)


class FRACTERRA_PT_polyline(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Polyline"
    shows = staticmethod(is_polyline)

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        settings = active_object(context).fracterra_polyline
        draw_regenerate(layout, settings, POLYLINE_REGENERATE)
        draw_polyline_settings(layout, settings, compact=True)


class FRACTERRA_PT_measures(_SidebarPanel, bpy.types.Panel):
    bl_label = "Fractal Measures"
    shows = staticmethod(is_measurable)

    def draw(self, context):
        layout = self.layout
        obj = active_object(context)
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
