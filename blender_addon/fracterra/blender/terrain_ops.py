"""Operators: Add > Mesh > Fractal Terrain, and regenerate in place."""

import bpy
from bpy_extras import object_utils
from bpy_extras.io_utils import ImportHelper

from ..core import params
from . import props
from .reporting import REPORTED
from .settings_ui import draw_settings
from .terrain_build import new_terrain_mesh, regenerate_object
from .widgets import draw_size


class FRACTERRA_OT_terrain_add(bpy.types.Operator, object_utils.AddObjectHelper):
    """Add a fractal terrain mesh (midpoint displacement, additions, fBm, spectral, interpolated)"""
    bl_idname = "mesh.fracterra_terrain_add"
    bl_label = "Fractal Terrain"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    def draw(self, context):
        draw_settings(self.layout, self)
        draw_size(self.layout, params.values_of(self))
        col = self.layout.column()
        col.use_property_split = True
        col.prop(self, "align")
        col.prop(self, "location")
        col.prop(self, "rotation")

    def execute(self, context):
        values = params.values_of(self)
        try:
            mesh, summary = new_terrain_mesh(values, context)
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        obj = object_utils.object_data_add(context, mesh, operator=self)
        settings = obj.fracterra_terrain
        props.copy_settings(self, settings)
        settings.is_terrain = True
        self.report({"INFO"}, f"Fractal terrain: {summary}")
        return {"FINISHED"}


# The operator's properties come from the same list as the object's settings.
FRACTERRA_OT_terrain_add.__annotations__ = {**props.terrain_annotations()}


class FRACTERRA_OT_terrain_regenerate(bpy.types.Operator):
    """Regenerate the active fractal terrain from its settings (heights only when the grid size is unchanged)"""
    bl_idname = "object.fracterra_terrain_regenerate"
    bl_label = "Regenerate Terrain"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return (obj is not None and obj.type == "MESH" and context.mode == "OBJECT"
                and obj.fracterra_terrain.is_terrain)

    def execute(self, context):
        obj = context.active_object
        try:
            summary = regenerate_object(obj, context)
        except REPORTED as e:
            obj.fracterra_terrain.last_error = str(e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        obj.fracterra_terrain.last_error = ""
        self.report({"INFO"}, f"Fractal terrain: {summary}")
        return {"FINISHED"}



class FRACTERRA_OT_reference_image_open(bpy.types.Operator, ImportHelper):
    """Open an image file as the active terrain's reference (its brightness becomes the heights)"""
    bl_idname = "object.fracterra_reference_image_open"
    bl_label = "Open Reference Image"
    bl_options = {"REGISTER", "UNDO"}

    filter_glob: bpy.props.StringProperty(
        default="*.png;*.jpg;*.jpeg;*.tif;*.tiff;*.exr;*.hdr;*.bmp;*.tga;*.webp", options={"HIDDEN"})

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and obj.fracterra_terrain.is_terrain

    def execute(self, context):
        try:
            image = bpy.data.images.load(self.filepath, check_existing=True)
        except RuntimeError as e:  # Blender's own message: missing file, unknown format
            self.report({"ERROR"}, f"cannot open '{self.filepath}' as an image: {e}")
            return {"CANCELLED"}
        settings = context.active_object.fracterra_terrain
        settings.reference_image = image.name
        settings.reference_source = "IMAGE"
        self.report({"INFO"}, f"Reference image: {image.name} ({image.size[0]} x {image.size[1]})")
        return {"FINISHED"}
