"""The sidebar panel (View3D > Sidebar > Fracterra) and the add-on preferences."""

import textwrap

import bpy

from .. import core
from . import props
from .terrain_ops import FRACTERRA_OT_terrain_add, FRACTERRA_OT_terrain_regenerate

ROOT_PACKAGE = __package__.rpartition(".")[0]


def draw_wrapped(layout, text, icon="NONE", width=60, alert=False):
    col = layout.column(align=True)
    col.alert = alert
    for i, line in enumerate(textwrap.wrap(text, width)):
        col.label(text=line, icon=icon if i == 0 else "BLANK1")


def draw_library_problem(layout):
    """Shows why the library cannot be used and what to do; False when it can."""
    ok, message = core.status()
    if not ok:
        draw_wrapped(layout.box(), message, icon="ERROR", alert=True)
    return not ok


class FRACTERRA_PT_terrain(bpy.types.Panel):
    bl_label = "Fractal Terrain"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Fracterra"

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        obj = context.active_object
        settings = getattr(obj, "fracterra_terrain", None) if obj is not None else None
        if settings is None or not settings.is_terrain:
            layout.label(text="The active object is not a fractal terrain.")
            layout.operator(FRACTERRA_OT_terrain_add.bl_idname, text="Add Fractal Terrain", icon="RNDCURVE")
            return
        row = layout.row(align=True)
        row.operator(FRACTERRA_OT_terrain_regenerate.bl_idname, text="Regenerate", icon="FILE_REFRESH")
        row.prop(settings, "auto_update", text="", icon="AUTO", toggle=True)
        if settings.last_error:
            draw_wrapped(layout, settings.last_error, icon="ERROR", alert=True)
        props.draw_settings(layout, settings)


class FracterraPreferences(bpy.types.AddonPreferences):
    bl_idname = ROOT_PACKAGE

    threads: bpy.props.IntProperty(
        name="Threads", default=0, min=0, max=1024,
        description="Threads the library uses for generation (0: all cores). Results never depend on it; "
                    "1 can be faster when other programs keep every core busy")

    def draw(self, context):
        layout = self.layout
        if not draw_library_problem(layout):
            draw_wrapped(layout, core.status()[1], icon="CHECKMARK")
        layout.prop(self, "threads")


def preferences(context):
    """The add-on's preferences, or None when it runs unregistered from a script."""
    addon = context.preferences.addons.get(ROOT_PACKAGE)
    return addon.preferences if addon else None
