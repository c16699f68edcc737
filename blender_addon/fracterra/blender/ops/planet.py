# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators: Add > Mesh > Fractal Planet, and regenerate in place (as terrains)."""

import bpy
from bpy_extras import object_utils

from ...core import params
from ..ui import properties as props
from ..common.jobs import JobOperator
from ..ui.planet_layout import draw_planet_settings
from ..build import planet as planet_build
from ..build.water import take as take_sea
from ..common.widgets import draw_placement
from .regenerate import RegenerateOperator


class FRACTERRA_OT_planet_add(JobOperator, bpy.types.Operator, object_utils.AddObjectHelper):
    """Add a fractal planet: a closed cube-sphere mesh of spherical fBm, with a sea sphere and a material by height, slope and latitude"""
    bl_idname = "mesh.fracterra_planet_add"
    bl_label = "Fractal Planet"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    def draw(self, context):
        draw_planet_settings(self.layout, self)
        draw_placement(self.layout, self)

    # As Add Terrain: from the menu a background job (progress bar, Esc
    # cancels) builds the Final level; the redo panel reruns execute() on every
    # change and builds the Preview level there (Regenerate builds the Final).
    def make_job(self, context):
        values = params.values_of(self, params.PLANET_OBJECT_PARAMS)
        self._preview = self.options.is_repeat and params.planet_preview_values(values) is not values
        return planet_build.new_planet_job(values, context, preview=self._preview)

    def job_done(self, context, value):
        mesh, summary = value
        obj = object_utils.object_data_add(context, mesh, operator=self)
        settings = obj.fracterra_planet
        props.copy_settings(self, settings, params.PLANET_OBJECT_PARAMS)
        settings.is_planet = True
        sea = planet_build.build_sea(obj, take_sea(mesh))
        if sea:
            summary = f"{summary}; {sea}"
        if getattr(self, "_preview", False):
            self.report({"INFO"}, f"Fractal planet: Preview, {summary} in {self.job_seconds:.2f} s; "
                                  "Build Final in the sidebar builds Level")
        else:
            self.report({"INFO"}, f"Fractal planet: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}


FRACTERRA_OT_planet_add.__annotations__ = props.terrain_annotations(param_list=params.PLANET_OBJECT_PARAMS)


class FRACTERRA_OT_planet_regenerate(RegenerateOperator, bpy.types.Operator):
    """Regenerate the active fractal planet from its settings at its Final level (positions only when the level is unchanged)"""
    bl_idname = "object.fracterra_planet_regenerate"
    bl_label = "Regenerate Planet"
    bl_options = {"REGISTER", "UNDO"}
    noun = "planet"
    target_of = staticmethod(planet_build.planet_of)
    regenerate_job = staticmethod(planet_build.regenerate_job)
