"""File > Export > POV-Ray (fracterra): terrains as height_field, curves as
chunked sphere_sweeps, the scene's camera and sun directions."""

import math

import bpy
from bpy_extras.io_utils import ExportHelper
from mathutils import Matrix, Vector

from ... import core
from ...core import povray
from ..build.curve import curve_polylines
from ..common.reporting import REPORTED, SettingsError
from ..build.objects import heightfield_of, is_terrain, sea_height


def _direction_angles(v):
    """(azimuth, elevation) in degrees of a direction: azimuth 0 = +y, 90 = +x."""
    v = v.normalized()
    azimuth = math.degrees(math.atan2(v.x, v.y))
    elevation = math.degrees(math.asin(max(-1.0, min(1.0, v.z))))
    return azimuth, min(90.0, max(1.0, elevation))


class FRACTERRA_OT_export_pov(bpy.types.Operator, ExportHelper):
    """Export the fractal terrain and curves as a POV-Ray scene (optionally render it)"""
    bl_idname = "export_scene.fracterra_pov"
    bl_label = "Export POV-Ray (fracterra)"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    filename_ext = ".pov"
    filter_glob: bpy.props.StringProperty(default="*.pov", options={"HIDDEN"})
    include_curves: bpy.props.BoolProperty(name="Curves", default=True,
                                           description="Export visible curve objects as sphere sweeps")
    use_scene_camera: bpy.props.BoolProperty(
        name="Scene Camera and Sun", default=True,
        description="Take the view and sun directions from the scene's camera and first sun lamp")
    render: bpy.props.BoolProperty(name="Render", default=False,
                                   description="Render the scene with povray into a PNG beside it")
    width: bpy.props.IntProperty(name="Width", default=640, min=16, max=8192, subtype="PIXEL")
    height: bpy.props.IntProperty(name="Height", default=480, min=16, max=8192, subtype="PIXEL")
    antialias: bpy.props.FloatProperty(name="Anti-aliasing", default=0.3, min=0.0, max=3.0,
                                       description="POV-Ray anti-aliasing threshold (0 = off)")

    def execute(self, context):
        try:
            message = self.export(context)
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, message)
        return {"FINISHED"}

    def export(self, context):
        scene = context.scene
        visible = [o for o in scene.objects if o.visible_get()]
        active = context.active_object
        terrain = active if is_terrain(active) else next((o for o in visible if is_terrain(o)), None)
        hf = None
        line_sets = []
        try:
            if terrain is not None:
                hf = heightfield_of(terrain)
                settings = terrain.fracterra_terrain
                world_size_x, world_size_y = core.grid_size(settings.world_size, hf.width, hf.height)
                frame = terrain.matrix_world.inverted()
                shift = Vector((world_size_x / 2, world_size_y / 2, 0.0))  # the writer's terrain spans 0..size
                water = sea_height(settings, hf.stats()["min"])
            else:
                world_size_x = world_size_y = 1.0
                frame, shift, water = Matrix.Identity(4), Vector((0, 0, 0)), None
            if self.include_curves:
                for obj in visible:
                    if obj.type == "CURVE":
                        pl = curve_polylines(obj, frame @ obj.matrix_world, shift)
                        if pl is not None:
                            kind = obj.get("fracterra_kind", "LINE")
                            kind = kind if kind in povray.LINE_KINDS else "LINE"
                            line_sets.append((pl, kind, 0.0))
            if hf is None and not line_sets:
                raise SettingsError("nothing to export: no fractal terrain and no curves are visible")
            camera = sun = None
            if self.use_scene_camera:
                centre = Vector((0.0, 0.0, 0.0))
                if scene.camera is not None and scene.camera.type == "CAMERA":
                    az, el = _direction_angles(frame @ scene.camera.matrix_world.translation - centre)
                    r = scene.render
                    camera = {"azimuth": az, "elevation": el,
                              "fov": min(150.0, max(5.0, math.degrees(scene.camera.data.angle_x))),
                              "aspect": min(10.0, max(0.1, r.resolution_x * r.pixel_aspect_x /
                                                      (r.resolution_y * r.pixel_aspect_y)))}
                lamp = next((o for o in visible if o.type == "LIGHT" and o.data.type == "SUN"), None)
                if lamp is not None:
                    to_sun = frame.to_3x3() @ lamp.matrix_world.to_3x3() @ Vector((0.0, 0.0, 1.0))
                    az, el = _direction_angles(to_sun)
                    sun = {"azimuth": az, "elevation": el}
            povray.write_scene(self.filepath, terrain=hf, world_size_x=world_size_x, world_size_y=world_size_y, sea_level=water,
                               line_sets=line_sets, camera=camera, sun=sun)
        finally:
            if hf is not None:
                hf.close()
            for pl, _, _ in line_sets:
                pl.close()
        message = f"POV-Ray scene written to {self.filepath}"
        if self.render:
            png = self.filepath[:-4] + ".png" if self.filepath.endswith(".pov") else self.filepath + ".png"
            povray.render(self.filepath, png, self.width, self.height, self.antialias)
            message += f", rendered to {png}"
        return message

