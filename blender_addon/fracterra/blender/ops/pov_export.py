# SPDX-License-Identifier: GPL-3.0-or-later
"""File > Export > POV-Ray (fracterra): the Blender scene as a POV-Ray scene:
the terrain as a height_field in its material's colours, curves as chunked
sphere_sweeps in their materials, rivers and lakes as water, other meshes as
mesh2, every light at its colour and power, the world's colour as the sky,
seen through the scene's camera at the render size the dialog or the scene
sets. pov_scene.py reads the scene; the library converts it (docs/povray.md)."""

import math
from contextlib import contextmanager

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
from . import pov_scene
from .pov_scene import DEFAULT_GREY, material_of, object_material


def _direction_angles(v):
    """(azimuth, elevation) in degrees of a direction: azimuth 0 = +y, 90 = +x."""
    v = v.normalized()
    azimuth = math.degrees(math.atan2(v.x, v.y))
    elevation = math.degrees(math.asin(max(-1.0, min(1.0, v.z))))
    return azimuth, min(90.0, max(1.0, elevation))


@contextmanager
def render_size(scene, width, height):
    """The scene's render resolution set to width x height at 100% (pixel aspect 1) for as long
    as the block runs, so Blender's own camera code fits the sensor to that image."""
    r = scene.render
    kept = (r.resolution_x, r.resolution_y, r.resolution_percentage, r.pixel_aspect_x, r.pixel_aspect_y)
    try:
        r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
        r.pixel_aspect_x = r.pixel_aspect_y = 1.0
        yield
    finally:
        (r.resolution_x, r.resolution_y, r.resolution_percentage, r.pixel_aspect_x, r.pixel_aspect_y) = kept


def scene_resolution(scene):
    """The scene's render size in pixels: Resolution X and Y times its percentage."""
    r = scene.render
    k = r.resolution_percentage / 100.0
    return max(16, min(8192, round(r.resolution_x * k))), max(16, min(8192, round(r.resolution_y * k)))


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
    material = object_material(obj)
    n = len(obj.data.vertices)
    if is_terrain_material(material):
        colors = attribute_colors(obj.data)
        if colors is not None:
            return colors
    colour = DEFAULT_GREY if material is None else material_of(material)["color"]
    return np.tile(np.asarray(colour, dtype=np.float32), n)


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
        name="Scene Camera", default=True,
        description="See through the scene's camera (position, rotation, lens and sensor fit); off: a camera "
                    "framed on the terrain and curves")
    use_scene_look: bpy.props.BoolProperty(
        name="Blender Look", default=True,
        description="Light and colour as Blender does: every light at its colour and power, the world colour "
                    "as sky and ambient light, each object in its material (rivers and lakes as water); off: "
                    "the terrain's splat colours under fracterra's sky, sun (the first sun's direction) and sea")
    render: bpy.props.BoolProperty(name="Render", default=False,
                                   description="Render the scene with povray into a PNG beside it")
    use_scene_resolution: bpy.props.BoolProperty(
        name="Scene Resolution", default=True,
        description="Render at the scene's resolution (Output Properties: Resolution X, Y and %); off: at "
                    "Width x Height, the camera fitted to that image as Blender fits it (its sensor fit)")
    width: bpy.props.IntProperty(name="Width", default=640, min=16, max=8192, subtype="PIXEL",
                                 description="Render width (with Scene Resolution off)")
    height: bpy.props.IntProperty(name="Height", default=480, min=16, max=8192, subtype="PIXEL",
                                  description="Render height (with Scene Resolution off)")
    antialias: bpy.props.FloatProperty(name="Anti-aliasing", default=0.3, min=0.0, max=3.0,
                                       description="POV-Ray anti-aliasing threshold (0 = off)")

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        for name in ("include_curves", "use_scene_camera", "use_scene_look", "render", "use_scene_resolution"):
            layout.prop(self, name)
        column = layout.column(align=True)
        column.enabled = not self.use_scene_resolution
        column.prop(self, "width")
        column.prop(self, "height")
        if self.use_scene_resolution:
            w, h = scene_resolution(context.scene)
            layout.label(text=f"Scene: {w} x {h} pixels")
        layout.prop(self, "antialias")

    def execute(self, context):
        try:
            message = self.export(context)
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, message)
        return {"FINISHED"}

    def image_size(self, scene):
        """The render size: the scene's resolution and percentage, or Width x Height with Scene
        Resolution off (a script that gives a width or height and says nothing of Scene
        Resolution means its own size too)."""
        props = self.properties
        given = (props.is_property_set("width") or props.is_property_set("height")) and \
            not props.is_property_set("use_scene_resolution")
        if self.use_scene_resolution and not given:
            return scene_resolution(scene)
        return self.width, self.height

    def export(self, context):
        scene = context.scene
        visible = [o for o in scene.objects if o.visible_get() and not o.hide_render]
        active = context.active_object
        terrain = active if is_terrain(active) else next((o for o in visible if is_terrain(o)), None)
        hf = colors = light = rivers = water_material = None
        line_sets, meshes, skipped, lights = [], [], [], []
        width, height = self.image_size(scene)
        look = self.use_scene_look
        try:
            if terrain is not None:
                hf = heightfield_of(terrain)
                settings = terrain.fracterra_terrain
                world_size_x, world_size_y = core.grid_size(settings.world_size, hf.width, hf.height)
                frame = terrain.matrix_world.inverted()
                shift = Vector((world_size_x / 2, world_size_y / 2, 0.0))  # the writer's terrain spans 0..size
                # Blender shows no sea but the water objects it holds.
                water = None if look else sea_height(settings, hf.stats()["min"])
                # The splat colours either way (the same map the material shows);
                # Blender Look also follows another material or none.
                colors = terrain_colors(terrain) if look else attribute_colors(terrain.data)
            else:
                world_size_x = world_size_y = 1.0
                frame, shift, water = Matrix.Identity(4), Vector((0, 0, 0)), None
            if self.include_curves:
                for obj in visible:
                    if obj.type != "CURVE":
                        continue
                    kind = obj.get("fracterra_kind", "LINE")
                    if kind == "RIVERS":
                        if not look:
                            continue  # fracterra's look draws no water but its sea
                        # Their bevel is a flat ellipse as wide as each point's radius.
                        rivers = curve_polylines(obj, frame @ obj.matrix_world, shift, radius_scale=1.0)
                        water_material = material_of(object_material(obj), water=True)
                        continue
                    pl = curve_polylines(obj, frame @ obj.matrix_world, shift)
                    if pl is not None:
                        kind = kind if kind in povray.LINE_KINDS else "LINE"
                        material = material_of(object_material(obj)) if look else None
                        line_sets.append((pl, kind, 0.0, material))
            if look:
                meshes, skipped = pov_scene.scene_meshes(visible, terrain, context.evaluated_depsgraph_get(),
                                                         frame, shift)
                if water_material is None:
                    water_material = next((m for _, m, _ in meshes if m["water"]), None)
            if hf is None and not line_sets and not meshes:
                raise SettingsError("nothing to export: no fractal terrain, curves or meshes are visible")
            camera = sun = None
            lamp = next((o for o in visible if o.type == "LIGHT" and o.data.type == "SUN"), None)
            if look:
                light = {"sky": pov_scene.world_sky(scene), "sun": (0.0, 0.0, 0.0)}
                lights = pov_scene.scene_lights(visible, frame, shift)
            elif lamp is not None:
                to_sun = frame.to_3x3() @ lamp.matrix_world.to_3x3() @ Vector((0.0, 0.0, 1.0))
                az, el = _direction_angles(to_sun)
                sun = {"azimuth": az, "elevation": el}
            if self.use_scene_camera and scene.camera is not None and scene.camera.type == "CAMERA":
                if scene.camera.data.type == "PERSP":
                    with render_size(scene, width, height):
                        camera = given_camera(scene, scene.camera, frame, shift)
                else:  # orthographic or panoramic: framed from its direction
                    az, el = _direction_angles(frame @ scene.camera.matrix_world.translation)
                    camera = {"azimuth": az, "elevation": el,
                              "fov": min(150.0, max(5.0, math.degrees(scene.camera.data.angle_x))),
                              "aspect": min(10.0, max(0.1, width / height))}
            elif not self.use_scene_camera:
                camera = {"azimuth": 200.0, "elevation": 0.0, "aspect": min(10.0, max(0.1, width / height))}
            povray.write_scene(self.filepath, terrain=hf, world_size_x=world_size_x, world_size_y=world_size_y,
                               sea_level=water, line_sets=line_sets, camera=camera, sun=sun, colors=colors,
                               light=light, lights=lights, rivers=rivers, water_material=water_material,
                               meshes=meshes)
        finally:
            for handle in [hf, rivers] + [ls[0] for ls in line_sets] + [m[0] for m in meshes]:
                if handle is not None:
                    handle.close()
        message = f"POV-Ray scene written to {self.filepath}"
        if skipped:
            message += "; left out: " + "; ".join(skipped)
        if self.render:
            png = self.filepath[:-4] + ".png" if self.filepath.endswith(".pov") else self.filepath + ".png"
            povray.render(self.filepath, png, width, height, self.antialias)
            message += f", rendered to {png} ({width} x {height})"
        return message
