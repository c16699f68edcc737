# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators: Add > Mesh > Fractal Terrain, and regenerate in place."""

import bpy
from bpy_extras import object_utils
from bpy_extras.io_utils import ImportHelper

from ...core import params
from ..ui import erosion_layout
from ..ui import properties as props
from ..common.jobs import JobOperator
from ..ui.settings_layout import draw_settings
from .regenerate import RegenerateOperator
from ..build.terrain import build_water, new_terrain_job, regenerate_job
from ..build import children, kept_final
from ..build.objects import active_object, mesh_level, restore_settings
from ..build.water import take as take_water, terrain_of
from ..common.jobs import run_job
from ..common.preferences import library_threads
from ..common.reporting import REPORTED
from ..common.widgets import draw_placement, draw_size


class FRACTERRA_OT_terrain_add(JobOperator, bpy.types.Operator, object_utils.AddObjectHelper):
    """Add a fractal terrain mesh (midpoint displacement, additions, fBm, spectral, interpolated)"""
    bl_idname = "mesh.fracterra_terrain_add"
    bl_label = "Fractal Terrain"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    def draw(self, context):
        draw_settings(self.layout, self)
        draw_size(self.layout, params.values_of(self))
        draw_placement(self.layout, self)

    # From the menu it runs in the background with a progress bar (Esc
    # cancels); the redo panel and scripts run execute() (progress.JobOperator).
    def make_job(self, context):
        # The redo panel runs execute() again on every change, with no progress
        # and no Esc: a terrain over its Preview size is built there at its
        # Preview level, and the sidebar's Build Final (a cancellable job with
        # progress) builds the rest. The menu and scripts build the Final.
        # A preset given as an argument (a script, a saved operator preset) shows
        # its own settings, as picking it in the menu does.
        erosion_layout.settle_preset(self)
        values = params.values_of(self)
        self._preview = self.options.is_repeat and params.preview_values(values) is not values
        # Where the object will stand: a mask object is seen over that footprint.
        return new_terrain_job(values, context, frame=object_utils.add_object_align_init(context, self),
                               preview=self._preview)

    def job_done(self, context, value):
        mesh, summary = value
        obj = object_utils.object_data_add(context, mesh, operator=self)
        settings = obj.fracterra_terrain
        props.copy_settings(self, settings)
        settings.is_terrain = True
        water = build_water(obj, take_water(mesh))
        if water:
            summary = f"{summary}; {water}"
        if getattr(self, "_preview", False):
            self.report({"INFO"}, f"Fractal terrain: Preview, {summary} in {self.job_seconds:.2f} s; "
                                  "Build Final in the sidebar builds Levels")
        else:
            self.report({"INFO"}, f"Fractal terrain: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}


# The operator's properties come from the same list as the object's settings.
# Erosion is not remembered from one Add to the next (SKIP_SAVE): a new terrain
# starts without erosion, or with the operator preset's, never silently with
# the last object's (the redo panel keeps it while adjusting this Add).
FRACTERRA_OT_terrain_add.__annotations__ = {
    **props.terrain_annotations(),
    **props.terrain_annotations(param_list=params.EROSION_PARAMS + params.EROSION_MAP_PARAMS, options={"SKIP_SAVE"}),
    # Rivers and Lakes, likewise: a new terrain starts without them unless asked.
    **props.terrain_annotations(param_list=params.RIVERS_PARAMS, options={"SKIP_SAVE"}),
    "erode_preset": erosion_layout.preset_property(options={"SKIP_SAVE"})}


class FRACTERRA_OT_terrain_regenerate(RegenerateOperator, bpy.types.Operator):
    """Regenerate the active fractal terrain from its settings at its Final level (heights only when the grid size is unchanged)"""
    bl_idname = "object.fracterra_terrain_regenerate"
    bl_label = "Regenerate Terrain"
    bl_options = {"REGISTER", "UNDO"}
    noun = "terrain"
    # The active terrain, or the terrain of the active water object or coastline.
    target_of = staticmethod(terrain_of)
    regenerate_job = staticmethod(regenerate_job)


class FRACTERRA_OT_back_to_final(bpy.types.Operator):
    """Show the Final kept beside the Preview again, with the settings it was built from (the Preview and the edits since are dropped; Build Final builds a new Final instead)"""
    bl_idname = "object.fracterra_back_to_final"
    bl_label = "Back to Final"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        terrain = terrain_of(active_object(context))
        return context.mode == "OBJECT" and terrain is not None and kept_final.kept(terrain) is not None

    def execute(self, context):
        terrain = terrain_of(active_object(context))
        kept_final.bring_back(terrain, water=True)
        restore_settings(terrain)
        terrain.fracterra_terrain.last_error = ""
        try:
            summary = run_job(children.follow_job(terrain, library_threads(context)))
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        level = mesh_level(terrain)
        shown = f"{level[1]} x {level[2]}" if level else "its mesh"
        self.report({"INFO"}, f"'{terrain.name}': back to its Final, {shown}" + (f"; {summary}" if summary else ""))
        return {"FINISHED"}


class FRACTERRA_OT_reference_image_open(bpy.types.Operator, ImportHelper):
    """Open an image file for the active terrain: its reference (brightness becomes the heights), its falloff mask, where it erodes or where rain falls"""
    bl_idname = "object.fracterra_reference_image_open"
    bl_label = "Open Image"
    bl_options = {"REGISTER", "UNDO"}

    filter_glob: bpy.props.StringProperty(
        default="*.png;*.jpg;*.jpeg;*.tif;*.tiff;*.exr;*.hdr;*.bmp;*.tga;*.webp", options={"HIDDEN"})
    target: bpy.props.EnumProperty(
        name="For", items=(("REFERENCE", "Reference", "The reference heights (Reference: Image)"),
                           ("FALLOFF_MASK", "Falloff Mask", "The custom falloff's mask (Mask From: Image)"),
                           ("EROSION_MASK", "Erosion Mask", "Where erosion acts (Mask: Image)"),
                           ("RAIN_MAP", "Rain Map", "Where rain falls (Rain Map: Image)")),
        default="REFERENCE", options={"HIDDEN", "SKIP_SAVE"})

    @classmethod
    def poll(cls, context):
        obj = active_object(context)
        return obj is not None and obj.type == "MESH" and obj.fracterra_terrain.is_terrain

    def execute(self, context):
        try:
            image = bpy.data.images.load(self.filepath, check_existing=True)
        except RuntimeError as e:  # Blender's own message: missing file, unknown format
            self.report({"ERROR"}, f"cannot open '{self.filepath}' as an image: {e}")
            return {"CANCELLED"}
        settings = active_object(context).fracterra_terrain
        if self.target == "FALLOFF_MASK":
            settings.falloff_mask_image = image.name
            settings.falloff_mask_source = "IMAGE"
            what = "Falloff mask"
        elif self.target in ("EROSION_MASK", "RAIN_MAP"):
            prefix = self.target.lower()
            setattr(settings, prefix + "_image", image.name)
            setattr(settings, prefix + "_source", "IMAGE")
            what = "Erosion mask" if self.target == "EROSION_MASK" else "Rain map"
        else:
            settings.reference_image = image.name
            settings.reference_source = "IMAGE"
            what = "Reference image"
        self.report({"INFO"}, f"{what}: {image.name} ({image.size[0]} x {image.size[1]})")
        return {"FINISHED"}
