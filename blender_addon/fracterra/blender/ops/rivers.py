# SPDX-License-Identifier: GPL-3.0-or-later
"""Operator: Rivers and Lakes of a terrain. It switches the terrain's Rivers
and Lakes setting on (or off) and regenerates the terrain, so the rivers come
from the library's pipeline with everything else (ft_terrain_build_rivers)
and Regenerate retraces them; water.py builds the objects."""

import bpy

from ..build.objects import active_object, mesh_level, restore_settings
from ..build.terrain import regenerate_job
from ..build.water import remove_water, terrain_of
from ..common.jobs import JobOperator

# Why Rivers and Lakes is greyed out, shown in its tooltip.
RIVERS_NEEDS = "Select a fractal terrain (or one of its water objects or its coastline) in Object Mode"


class FRACTERRA_OT_rivers(JobOperator, bpy.types.Operator):
    """Trace the rivers, lakes and sea of the active fractal terrain (stored with its settings: Regenerate retraces them)"""
    bl_idname = "object.fracterra_rivers"
    bl_label = "Rivers and Lakes"
    bl_options = {"REGISTER", "UNDO"}

    remove: bpy.props.BoolProperty(name="Remove", default=False, options={"SKIP_SAVE"},
                                   description="Remove the terrain's rivers, lakes and sea and switch them off")

    @classmethod
    def poll(cls, context):
        if context.mode == "OBJECT" and terrain_of(active_object(context)) is not None:
            return True
        cls.poll_message_set(RIVERS_NEEDS)
        return False

    def execute(self, context):
        if self.remove:
            terrain = terrain_of(active_object(context))
            terrain.fracterra_terrain.rivers = False
            remove_water(terrain)
            if context.view_layer.objects.active is None:
                context.view_layer.objects.active = terrain
            self.report({"INFO"}, f"Rivers and Lakes removed from '{terrain.name}'")
            return {"FINISHED"}
        return super().execute(context)

    def invoke(self, context, event):
        if self.remove:
            return self.execute(context)
        return super().invoke(context, event)

    def make_job(self, context):
        terrain = terrain_of(active_object(context))
        self._terrain_name = terrain.name
        settings = terrain.fracterra_terrain
        settings.last_error = ""
        settings.rivers = True
        # At the level the artist sees: over a Preview, the Preview (never a
        # Final built unasked); Build Final then traces the Final's.
        level = mesh_level(terrain)
        return regenerate_job(terrain, context, preview=level is not None and level[0] == "Preview")

    def _terrain(self):
        return bpy.data.objects.get(getattr(self, "_terrain_name", ""))

    def job_cancelled(self, context):
        obj = self._terrain()
        if obj is not None:
            restore_settings(obj)

    def _refuse(self, e):
        obj = self._terrain()
        if obj is not None:
            restore_settings(obj)
            obj.fracterra_terrain.last_error = str(e)
        return super()._refuse(e)

    def job_done(self, context, summary):
        self.report({"INFO"}, f"Rivers and Lakes: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}
