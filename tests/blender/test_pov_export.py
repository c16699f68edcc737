"""The POV-Ray export shows the Blender scene: known vertices land on the same
pixels through Blender's camera (bpy_extras' world_to_camera_view) and
through the camera statement the scene file holds (solved here from
POV-Ray's documented perspective model, not by the exporter's code); a
Cycles render and a POV-Ray render of the same scene cover the same pixels
with the terrain and colour it alike.

Set FT_POV_COMPARE_OUT to a folder to keep the renders for a look."""

import array
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402
import numpy as np  # noqa: E402
from bpy_extras.object_utils import world_to_camera_view  # noqa: E402
from mathutils import Euler, Vector  # noqa: E402

NUMBER = r"[-+0-9.eE]+"
VECTOR = rf"<\s*({NUMBER}),\s*({NUMBER}),\s*({NUMBER})\s*>"


clear_scene = addon_harness.clear_scene


def vector_after(text, keyword):
    m = re.search(rf"\b{keyword}\s+{VECTOR}", text)
    assert m, f"no '{keyword} <...>' in {text!r}"
    return np.array([float(g) for g in m.groups()])


def pov_camera(scene_text):
    """location, right, up, direction of the scene's camera statement."""
    block = re.search(r"camera\s*\{(.*?)\}", scene_text, re.S).group(1)
    return {k: vector_after(block, k) for k in ("location", "right", "up", "direction")}


def pov_pixel(cam, point, width, height):
    """POV-Ray's perspective camera: the ray of image point (u, v) (v down) runs
    from `location` along direction + (u - 0.5) right + (0.5 - v) up."""
    m = np.column_stack([cam["direction"], cam["right"], cam["up"]])
    t, ta, tb = np.linalg.solve(m, np.asarray(point) - cam["location"])
    return np.array([(0.5 + ta / t) * width, (0.5 - tb / t) * height])


def terrain_placement(scene_text):
    """(size x, size z) of the terrain's height_field: sample (i, j) of a
    w x h grid lies at POV x = i / (w - 1) * sx, z = j / (h - 1) * sz."""
    block = scene_text[scene_text.index("#declare FT_Terrain_Object = height_field"):]
    scales = re.findall(rf"scale\s+{VECTOR}", block)
    assert scales[0] == ("1", "1", "-1"), scales  # the mirror that puts image row 0 at z = 0
    return float(scales[1][0]), float(scales[1][2])


def render_cycles(path, samples=16):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.render.film_transparent = True
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGBA"
    scene.view_settings.view_transform = "Standard"  # POV-Ray writes plain sRGB
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)


def render_povray(pov, png, width, height):
    """The scene with its background made transparent (alpha 0 where no object
    is hit, as Cycles' transparent film), the rest as written."""
    text = Path(pov).read_text()
    masked = re.sub(r"background \{ rgb (<[^>]*>) \}", r"background { rgbt 1 }", text)
    assert masked != text, "no background statement"
    Path(pov).with_name("masked.pov").write_text(masked)
    subprocess.run(["povray", "+Imasked.pov", f"+O{png}", f"+W{width}", f"+H{height}", "+UA", "-D", "+A0.1",
                    "-GA", "+FN8"], check=True, capture_output=True, cwd=os.path.dirname(pov), timeout=120)


def read_rgba(path):
    """Linear RGB and alpha (rows from the top) of an 8-bit sRGB PNG through
    Blender's loader (which hands byte images over as stored)."""
    image = bpy.data.images.load(str(path))
    w, h = image.size
    px = np.empty(w * h * 4, dtype=np.float32)
    image.pixels.foreach_get(px)  # rows from the bottom
    bpy.data.images.remove(image)
    px = px.reshape(h, w, 4)[::-1].copy()
    c = px[..., :3]
    px[..., :3] = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return px


def mask_stats(a, b):
    """IoU of two masks and the distance between their centroids in pixels."""
    inter, union = np.logical_and(a, b).sum(), np.logical_or(a, b).sum()
    ca = np.argwhere(a).mean(axis=0)
    cb = np.argwhere(b).mean(axis=0)
    return inter / union, float(np.hypot(*(ca - cb)))


class PovExportMatchesBlender(unittest.TestCase):
    def setUp(self):
        clear_scene()
        self.keep = os.environ.get("FT_POV_COMPARE_OUT")
        self.dir = Path(tempfile.mkdtemp())

    def tearDown(self):
        if self.keep:
            os.makedirs(self.keep, exist_ok=True)
            for f in self.dir.glob("*.png"):
                shutil.copy(f, Path(self.keep, f"{self._testMethodName}-{f.name}"))
        shutil.rmtree(self.dir)

    def scene(self, resolution, camera_location, camera_rotation, lens=35.0, sensor_fit="AUTO", shift=(0.0, 0.0),
              terrain_matrix=None, **terrain):
        bpy.ops.mesh.fracterra_terrain_add(**terrain)
        obj = bpy.context.active_object
        if terrain_matrix is not None:
            location, rotation, scale = terrain_matrix
            obj.location, obj.rotation_euler, obj.scale = location, Euler(rotation), scale
        bpy.ops.object.camera_add(location=camera_location, rotation=camera_rotation)
        cam = bpy.context.active_object
        cam.data.lens, cam.data.sensor_fit = lens, sensor_fit
        cam.data.shift_x, cam.data.shift_y = shift
        bpy.ops.object.light_add(type="SUN", rotation=(0.6, 0.2, 0.9))
        bpy.context.active_object.data.energy = 3.0
        scene = bpy.context.scene
        scene.camera = cam
        scene.render.resolution_x, scene.render.resolution_y = resolution
        scene.render.resolution_percentage = 100
        bpy.context.view_layer.update()
        return obj, cam

    def export(self, obj):
        bpy.context.view_layer.objects.active = obj
        path = self.dir / "scene.pov"
        self.assertEqual(bpy.ops.export_scene.fracterra_pov(filepath=str(path)), {"FINISHED"})
        return path, path.read_text()

    def check_projection(self, obj, cam):
        """Corners, the peak and a few samples through both cameras. Tolerance
        0.01 px: the file's numbers have 9 significant digits, so a pixel moves
        by ~1e-6 of the image at worst; a real error in the lens, the frame or
        the aspect moves points by pixels."""
        scene = bpy.context.scene
        path, text = self.export(obj)
        w, h = scene.render.resolution_x, scene.render.resolution_y
        nx = ny = int(round(len(obj.data.vertices) ** 0.5))
        co = array.array("f", [0.0]) * (3 * len(obj.data.vertices))
        obj.data.vertices.foreach_get("co", co)
        z = np.frombuffer(co, dtype=np.float32)[2::3]
        sx, sz = terrain_placement(text)
        cam_pov = pov_camera(text)
        peak = int(np.argmax(z))
        picks = {0, nx - 1, nx * (ny - 1), nx * ny - 1, peak, nx * ny // 2 + nx // 3, nx * (ny // 3) + 2}
        for k in sorted(picks):
            i, j = k % nx, k // nx
            local = Vector(co[3 * k:3 * k + 3])
            ndc = world_to_camera_view(scene, cam, obj.matrix_world @ local)
            blender_px = np.array([ndc.x * w, (1 - ndc.y) * h])
            pov_px = pov_pixel(cam_pov, (i / (nx - 1) * sx, z[k], j / (ny - 1) * sz), w, h)
            self.assertLess(np.abs(blender_px - pov_px).max(), 0.01,
                            f"vertex {k} ({i}, {j}): Blender {blender_px}, POV-Ray {pov_px}")
        return path

    def test_vertices_land_on_the_same_pixels(self):
        obj, cam = self.scene((160, 90), (0, -14, 7), (1.1, 0, 0), levels=5, seed=3)
        self.check_projection(obj, cam)

    def test_a_moved_terrain_and_a_shifted_portrait_lens(self):
        obj, cam = self.scene((90, 120), (6, -9, 8), (0.95, 0.1, 0.6), lens=28, sensor_fit="VERTICAL",
                              shift=(0.12, -0.07), terrain_matrix=((1, 2, 0.5), (0.05, 0.0, 0.5), (1.3, 0.8, 1.6)),
                              levels=5, seed=4)
        self.check_projection(obj, cam)
        bpy.context.scene.render.resolution_x = 200  # another aspect: the exported frame follows it
        bpy.context.scene.render.resolution_y = 100
        cam.data.sensor_fit = "AUTO"
        self.check_projection(obj, cam)

    def test_cycles_and_povray_renders_agree(self):
        """The eroded terrain seen from a low oblique camera in both renderers at
        96 x 54: the terrain's mask (alpha) and its colours. Tolerances: an IoU of
        0.9 and 1 px between centroids allow the anti-aliased rim (a 1 px band is
        ~8% of this mask) and POV-Ray's smoothed height_field against Blender's
        flat-interpolated quads; the colour check compares each renderer's share of
        green per pixel (lighting-free) and the mean colour within 25%: the
        renderers share the material rule, the sun and the sky, not the
        Principled BSDF's sheen or the sky's occlusion."""
        obj, cam = self.scene((96, 54), (0, -13, 6.5), (1.13, 0, 0), levels=6, seed=5, erode_preset="LAND")
        world = bpy.context.scene.world
        world.use_nodes = True
        world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.3, 0.35, 0.45, 1.0)
        path, _ = self.export(obj)
        blender_png, pov_png = self.dir / "cycles.png", self.dir / "povray.png"
        render_cycles(blender_png)
        render_povray(path, pov_png, 96, 54)
        a, b = read_rgba(blender_png), read_rgba(pov_png)
        ma, mb = a[..., 3] > 0.5, b[..., 3] > 0.5
        self.assertGreater(ma.sum(), 0.1 * ma.size)  # the terrain fills a good part of the frame
        iou, centroid = mask_stats(ma, mb)
        print(f"mask IoU {iou:.3f}, centroids {centroid:.2f} px apart", flush=True)
        self.assertGreater(iou, 0.9)
        self.assertLess(centroid, 1.0)
        both = np.logical_and(ma, mb)
        ca, cb = a[both][:, :3], b[both][:, :3]
        green_a = ca[:, 1] / np.maximum(ca.sum(axis=1), 1e-6)
        green_b = cb[:, 1] / np.maximum(cb.sum(axis=1), 1e-6)
        corr = float(np.corrcoef(green_a, green_b)[0, 1])
        mean_a, mean_b = ca.mean(axis=0), cb.mean(axis=0)
        print(f"green share correlation {corr:.3f}; mean colour Cycles {mean_a}, POV-Ray {mean_b}", flush=True)
        self.assertGreater(corr, 0.7)
        self.assertLess(np.abs(mean_a - mean_b).max() / mean_a.max(), 0.25)

    def test_a_terrain_without_material_is_grey_in_both(self):
        obj, _ = self.scene((64, 36), (0, -13, 6.5), (1.13, 0, 0), levels=5, seed=2)
        obj.data.materials.clear()  # a terrain gets its splat material: take it away
        self.assertEqual(len(obj.material_slots), 0)
        path, text = self.export(obj)
        self.assertNotIn("FT_Terrain_Texture(", text.split("// ---- end of ft_scene_materials.inc ----")[1])
        colors = read_rgba(self.dir / "scene.colors.png")
        self.assertTrue(np.allclose(colors[..., :3], 0.8, atol=0.004), colors[0, 0])


if __name__ == "__main__":
    addon_harness.run(globals())
