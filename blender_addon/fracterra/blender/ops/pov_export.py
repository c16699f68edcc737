"""File > Export > POV-Ray (fracterra): terrains as height_field, curves as
chunked sphere_sweeps, seen through the scene's camera (position, rotation,
lens) and lit by its sun and world, the terrain coloured as its Blender
material colours it."""

import math

import bpy
import numpy as np
from bpy_extras.io_utils import ExportHelper
from mathutils import Matrix, Vector

from ... import core
from ...core import povray
from ..build.curve import curve_polylines
from ..build.splat_material import attribute_colors, is_terrain_material
from ..common.reporting import REPORTED, SettingsError
from ..build.objects import heightfield_of, is_terrain, sea_height

# Cycles shades a mesh without a material with a grey diffuse of this albedo.
DEFAULT_GREY = (0.8, 0.8, 0.8)


def _direction_angles(v):
    """(azimuth, elevation) in degrees of a direction: azimuth 0 = +y, 90 = +x."""
    v = v.normalized()
    azimuth = math.degrees(math.atan2(v.x, v.y))
    elevation = math.degrees(math.asin(max(-1.0, min(1.0, v.z))))
    return azimuth, min(90.0, max(1.0, elevation))


def given_camera(scene, camera, frame, shift):
    """A perspective scene camera as POV-Ray's vectors in the writer's frame
    (frame @ world + shift): its view frame (lens, sensor fit, shift and the
    render's aspect, as Blender computes them) at the eye's distance; an affine
    frame keeps every ray, so the vectors are carried over unnormalised."""
    top_right, _, bottom_left, top_left = camera.data.view_frame(scene=scene)
    to_world = camera.matrix_world.normalized()  # Blender renders without the camera's scale
    linear = frame.to_3x3() @ to_world.to_3x3()
    return {"location": tuple(frame @ to_world.translation + shift),
            "direction": tuple(linear @ ((top_right + bottom_left) / 2)),
            "right": tuple(linear @ (top_right - top_left)),
            "up": tuple(linear @ (top_left - bottom_left))}


def terrain_colors(obj):
    """Linear RGB per vertex (float32, 3 per vertex, in the grid's order) as
    Blender colours the terrain: the terrain material's colour attribute (the
    library's splat colours), another material's base colour, or Cycles' grey
    without a material."""
    material = next((slot.material for slot in obj.material_slots if slot.material is not None), None)
    n = len(obj.data.vertices)
    if is_terrain_material(material):
        colors = attribute_colors(obj.data)
        if colors is not None:
            return colors
    colour = DEFAULT_GREY
    if material is not None:
        colour = tuple(material.diffuse_color[:3])
        bsdf = material.node_tree.nodes.get("Principled BSDF") if material.use_nodes else None
        if bsdf is not None and not bsdf.inputs["Base Color"].is_linked:
            colour = tuple(bsdf.inputs["Base Color"].default_value[:3])
    return np.tile(np.asarray(colour, dtype=np.float32), n)


def scene_light(scene, lamp):
    """The world's colour (its Background node's colour times strength) and the
    sun lamp's colour times strength over pi, linear RGB: Cycles' sun of
    strength S is an irradiance of S W/m^2, which a white diffuse surface facing
    it returns as a radiance of S / pi, where POV-Ray's light colour is that
    radiance itself; a sky of radiance L returns L (POV-Ray's ambient_light)."""
    world, sky = scene.world, (0.0, 0.0, 0.0)
    if world is not None:
        sky = tuple(world.color)
        background = world.node_tree.nodes.get("Background") if world.use_nodes else None
        if background is not None and not background.inputs["Color"].is_linked:
            strength = background.inputs["Strength"].default_value
            sky = tuple(c * strength for c in background.inputs["Color"].default_value[:3])
    sun = (0.0, 0.0, 0.0) if lamp is None else tuple(c * lamp.data.energy / math.pi for c in lamp.data.color)
    return {"sky": sky, "sun": sun}


class FRACTERRA_OT_export_pov(bpy.types.Operator, ExportHelper):
    """Export the fractal terrain and curves as a POV-Ray scene (optionally render it)"""
    bl_idname = "export_scene.fracterra_pov"
    bl_label = "Export POV-Ray"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    filename_ext = ".pov"
    filter_glob: bpy.props.StringProperty(default="*.pov", options={"HIDDEN"})
    include_curves: bpy.props.BoolProperty(name="Curves", default=True,
                                           description="Export visible curve objects as sphere sweeps")
    use_scene_camera: bpy.props.BoolProperty(
        name="Scene Camera and Sun", default=True,
        description="See through the scene's camera (position, rotation and lens; render at its aspect) and "
                    "light from the first sun lamp's direction")
    use_scene_look: bpy.props.BoolProperty(
        name="Blender Look", default=True,
        description="Colour the terrain as its Blender material does (grey without one) and light it by the "
                    "world colour and the sun's colour and strength; off: the terrain's splat colours under "
                    "fracterra's sky, sun and sea")
    render: bpy.props.BoolProperty(name="Render", default=False,
                                   description="Render the scene with povray into a PNG beside it")
    width: bpy.props.IntProperty(name="Width", default=640, min=16, max=8192, subtype="PIXEL")
    height: bpy.props.IntProperty(name="Height", default=480, min=16, max=8192, subtype="PIXEL",
                                  description="Render height (unset: the width over the scene's render aspect)")
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
        hf = colors = light = None
        line_sets = []
        try:
            if terrain is not None:
                hf = heightfield_of(terrain)
                settings = terrain.fracterra_terrain
                world_size_x, world_size_y = core.grid_size(settings.world_size, hf.width, hf.height)
                frame = terrain.matrix_world.inverted()
                shift = Vector((world_size_x / 2, world_size_y / 2, 0.0))  # the writer's terrain spans 0..size
                # Blender shows no sea: its flat floor is part of the mesh, coloured as the rest.
                water = None if self.use_scene_look else sea_height(settings, hf.stats()["min"])
                # The splat colours either way (the same map the material shows);
                # Blender Look also follows another material or none.
                colors = terrain_colors(terrain) if self.use_scene_look else attribute_colors(terrain.data)
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
            lamp = next((o for o in visible if o.type == "LIGHT" and o.data.type == "SUN"), None)
            if self.use_scene_look:
                light = scene_light(scene, lamp)
            if self.use_scene_camera:
                centre = Vector((0.0, 0.0, 0.0))
                if scene.camera is not None and scene.camera.type == "CAMERA":
                    if scene.camera.data.type == "PERSP":
                        camera = given_camera(scene, scene.camera, frame, shift)
                    else:  # orthographic or panoramic: framed from its direction
                        az, el = _direction_angles(frame @ scene.camera.matrix_world.translation - centre)
                        r = scene.render
                        camera = {"azimuth": az, "elevation": el,
                                  "fov": min(150.0, max(5.0, math.degrees(scene.camera.data.angle_x))),
                                  "aspect": min(10.0, max(0.1, r.resolution_x * r.pixel_aspect_x /
                                                          (r.resolution_y * r.pixel_aspect_y)))}
                if lamp is not None:
                    to_sun = frame.to_3x3() @ lamp.matrix_world.to_3x3() @ Vector((0.0, 0.0, 1.0))
                    az, el = _direction_angles(to_sun)
                    sun = {"azimuth": az, "elevation": el}
            povray.write_scene(self.filepath, terrain=hf, world_size_x=world_size_x, world_size_y=world_size_y,
                               sea_level=water, line_sets=line_sets, camera=camera, sun=sun, colors=colors,
                               light=light)
        finally:
            if hf is not None:
                hf.close()
            for pl, _, _ in line_sets:
                pl.close()
        message = f"POV-Ray scene written to {self.filepath}"
        if self.render:
            png = self.filepath[:-4] + ".png" if self.filepath.endswith(".pov") else self.filepath + ".png"
            width, height = self.width, self.height
            if not self.properties.is_property_set("height"):
                # The scene camera's aspect is its render's: the height follows the width.
                r = scene.render
                aspect = r.resolution_x * r.pixel_aspect_x / (r.resolution_y * r.pixel_aspect_y)
                height = max(16, min(8192, round(width / aspect)))
            povray.render(self.filepath, png, width, height, self.antialias)
            message += f", rendered to {png}"
        return message

