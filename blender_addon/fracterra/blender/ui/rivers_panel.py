# SPDX-License-Identifier: GPL-3.0-or-later
"""The sidebar's Rivers and Lakes panel (View3D > Sidebar > Fracterra), shown
for a terrain and for its water objects and coastline: the terrain's Rivers
and Lakes settings and the operator that traces them (by its id string)."""

import bpy

from .rivers_layout import draw_rivers
from ..build.objects import active_object
from ..build.water import terrain_of, water_objects
from ..common.widgets import draw_library_problem

RIVERS = "object.fracterra_rivers"


class FRACTERRA_PT_rivers(bpy.types.Panel):
    bl_label = "Rivers and Lakes"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Fracterra"

    @classmethod
    def poll(cls, context):
        return terrain_of(active_object(context)) is not None

    def draw(self, context):
        layout = self.layout
        draw_library_problem(layout)
        terrain = terrain_of(active_object(context))
        settings = terrain.fracterra_terrain
        made = water_objects(terrain)
        col = layout.column(align=True)
        col.operator(RIVERS, text="Retrace Rivers and Lakes" if made else "Trace Rivers and Lakes", icon="MOD_FLUIDSIM")
        if made:
            col.operator(RIVERS, text="Remove", icon="X").remove = True
        draw_rivers(layout, settings)
