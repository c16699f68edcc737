# SPDX-License-Identifier: GPL-3.0-or-later
"""The POV-Ray export shows the Blender scene: known vertices land on the same
pixels through Blender's camera (bpy_extras' world_to_camera_view) and
through the camera statement the scene file holds (solved here from
POV-Ray's documented perspective model, not by the exporter's code); a
Cycles render and a POV-Ray render of the same scene cover the same pixels
with the terrain and colour it alike.

Set FT_POV_COMPARE_OUT to a folder to keep the renders for a look."""

import array
import math
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

# Blender's default scene (--factory-startup): its point light and camera, kept
# before any test clears the scene (the light and camera data stay in the file).
FACTORY = {name: (obj.data.name, obj.matrix_world.copy()) for name, obj in bpy.data.objects.items()
           if obj.type in ("LIGHT", "CAMERA")}


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
        addon_harness.keep_renders(self.dir, self.keep, f"{self._testMethodName}-")

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



# ---- One scene, two renderers: Cycles and POV-Ray compared block by block ----

BLOCKS = 8
SIZE = (160, 90)


def block_means(rgb, n=BLOCKS):
    """(n, n, 3) means of linear RGB over an n x n grid of blocks (rows from the top)."""
    rows = np.array_split(np.arange(rgb.shape[0]), n)
    cols = np.array_split(np.arange(rgb.shape[1]), n)
    return np.array([[rgb[r[0]:r[-1] + 1, c[0]:c[-1] + 1].reshape(-1, 3).mean(axis=0) for c in cols] for r in rows])


def luminance(rgb):
    """Rec. 709 relative luminance of linear RGB (..., 3)."""
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def hue_and_chroma(rgb):
    """Hue angle (radians) and chroma relative to brightness of linear RGB (..., 3), from the
    opponent axes of the hexagonal hue model (HSV's hue, continuous)."""
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    alpha, beta = r - 0.5 * (g + b), np.sqrt(3.0) / 2.0 * (g - b)
    return np.arctan2(beta, alpha), np.hypot(alpha, beta) / np.maximum(rgb.sum(axis=-1) / 3.0, 1e-6)


def render_cycles_direct(path, samples, seed):
    """Cycles as POV-Ray traces: direct light and mirror reflections only (POV-Ray has no
    diffuse interreflection), on the CPU, without denoising, as plain sRGB."""
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device, c.samples, c.use_denoising, c.seed = "CPU", samples, False, seed
    c.max_bounces, c.diffuse_bounces, c.glossy_bounces = 2, 0, 2
    c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = 0
    scene.render.film_transparent = False
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure, scene.view_settings.gamma = 0.0, 1.0
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)


def principled_excess(roughness, samples=32):
    """How much brighter Cycles' Principled BSDF (base 0.3, Specular 0.5, this roughness) is than
    a Lambertian surface of the same colour, which is what the export writes: the log ratio of
    the two on a flat plane under a sun, over views from 20 to 75 degrees off the normal and sun
    elevations of 15, 40 and 70 degrees. Returns (smallest, largest)."""
    ratios = []
    scene = bpy.context.scene
    for view in (20, 50, 75):
        for tilt in (20, 50, 75):
            values = []
            for shader in ("ShaderNodeBsdfPrincipled", "ShaderNodeBsdfDiffuse"):
                clear_scene()
                bpy.ops.mesh.primitive_plane_add(size=200)
                mat = bpy.data.materials.new("calibration")
                mat.use_nodes = True
                nodes = mat.node_tree.nodes
                nodes.clear()
                bsdf = nodes.new(shader)
                bsdf.inputs[0].default_value = (0.3, 0.3, 0.3, 1)
                if shader == "ShaderNodeBsdfPrincipled":
                    bsdf.inputs["Roughness"].default_value = roughness
                out = nodes.new("ShaderNodeOutputMaterial")
                mat.node_tree.links.new(bsdf.outputs[0], out.inputs[0])
                bpy.context.active_object.data.materials.append(mat)
                v = math.radians(view)
                bpy.ops.object.camera_add(location=(0, -10 * math.sin(v), 10 * math.cos(v)), rotation=(v, 0, 0))
                scene.camera = bpy.context.active_object
                scene.camera.data.type, scene.camera.data.ortho_scale = "ORTHO", 0.5
                bpy.ops.object.light_add(type="SUN", rotation=(math.radians(tilt), 0, math.radians(200)))
                bpy.context.active_object.data.energy = 3.0
                scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
                scene.render.resolution_x = scene.render.resolution_y = 8
                path = Path(tempfile.mkdtemp()) / "calibration.png"
                render_cycles_direct(path, samples, 1)
                values.append(luminance(read_rgba(path)[..., :3].reshape(-1, 3).mean(axis=0)))
                shutil.rmtree(path.parent)
                bpy.data.materials.remove(mat)
            ratios.append(math.log(values[0] / values[1]))
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    clear_scene()
    return min(ratios), max(ratios)


class OneSceneTwoRenderers(unittest.TestCase):
    """The same scene rendered by Cycles and by POV-Ray from the add-on's export, compared as
    8 x 8 block means of luminance and hue at 160 x 90.

    Cycles renders as POV-Ray traces: direct light and mirror reflections, no light bounced off
    diffuse surfaces (POV-Ray has none without radiosity). What then still differs, and so makes
    the tolerance of a block's log luminance ratio log(POV-Ray / Cycles):
    - Cycles' Principled BSDF is brighter than the Lambertian surface POV-Ray is given (Disney
      diffuse's grazing retro-reflection and a broad specular lobe): measured here on a flat
      calibration plane in the terrain material's roughness, as log ratios in [rho_lo, rho_hi]
      (about 0.05 to 0.37): POV-Ray blocks may be darker by up to rho_hi;
    - Cycles' noise: two Cycles renders with other seeds differ by n at most per block (measured
      in each test); 3 n is allowed;
    - edges: POV-Ray's smooth height_field against Blender's flat quads and sharp shadows against
      soft ones move a boundary by about a pixel; across a block's 20-pixel side that is 20 of its
      at least 220 pixels, 9% of the contrast across it: log(1.1) = 0.1 is allowed.
    So every block lies in [-(rho_hi + m), m] with m = 3 n + 0.1, and the median of the blocks,
    whose edges and noise average out, in [-(rho_hi + 3 n), -rho_lo + 3 n + 0.05].
    Hue (blocks whose chroma is over 0.15 in both): the renderers share the colours, so hue moves
    only with noise (3 times the seeds' largest difference) and with the Principled excess, which
    brightens one light's share of a block against the other lights' and the sky's: measured by
    rendering POV-Ray again with each light, then all, exp(rho_hi) times brighter; the largest
    shift plus the noise plus 2 degrees (the 8-bit images' rounding of dark colours) is allowed."""

    @classmethod
    def setUpClass(cls):
        roughness = addon_harness.submodule("blender.build.splat_material").ROUGHNESS
        cls.rho_lo, cls.rho_hi = principled_excess(roughness)
        print(f"Principled over Lambert at roughness {roughness}: log ratio {cls.rho_lo:.3f} .. {cls.rho_hi:.3f}",
              flush=True)

    def setUp(self):
        clear_scene()
        for curve in list(bpy.data.curves):
            bpy.data.curves.remove(curve)
        self.keep = os.environ.get("FT_POV_COMPARE_OUT")
        self.dir = Path(tempfile.mkdtemp())
        scene = bpy.context.scene
        scene.render.resolution_x, scene.render.resolution_y = SIZE
        scene.render.resolution_percentage = 100
        world = scene.world
        world.use_nodes = True
        world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.0509, 0.0509, 0.0509, 1.0)
        world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0

    def tearDown(self):
        addon_harness.keep_renders(self.dir, self.keep, f"{self._testMethodName}-")

    def factory(self, kind):
        """The factory scene's light or camera object, back in the scene."""
        name = {"LIGHT": "Light", "CAMERA": "Camera"}[kind]
        data_name, matrix = FACTORY[name]
        data = (bpy.data.lights if kind == "LIGHT" else bpy.data.cameras)[data_name]
        obj = bpy.data.objects.new(name, data)
        bpy.context.scene.collection.objects.link(obj)
        obj.matrix_world = matrix
        if kind == "CAMERA":
            bpy.context.scene.camera = obj
        return obj

    def export_render(self, terrain, name):
        bpy.context.view_layer.objects.active = terrain
        pov = self.dir / f"{name}.pov"
        result = bpy.ops.export_scene.fracterra_pov(filepath=str(pov), render=True, antialias=0.1)
        self.assertEqual(result, {"FINISHED"})
        return read_rgba(self.dir / f"{name}.png")[..., :3]

    def renders(self, terrain):
        """Linear RGB of the scene: Cycles, Cycles with another seed, POV-Ray, and POV-Ray with one
        light at a time exp(rho_hi) times as strong (each light, then all: the Principled excess
        may favour any of them against the others and the sky)."""
        images = []
        for seed in (1, 2):
            png = self.dir / f"cycles{seed}.png"
            render_cycles_direct(png, 24, seed)
            images.append(read_rgba(png)[..., :3])
        images.append(self.export_render(terrain, "povray"))
        lights = [o.data for o in bpy.context.scene.objects if o.type == "LIGHT"]
        brighter = []
        for k, chosen in enumerate([[data] for data in lights] + ([lights] if len(lights) > 1 else [])):
            for data in chosen:
                data.energy *= math.exp(self.rho_hi)
            try:
                brighter.append(self.export_render(terrain, f"povray-brighter{k}"))
            finally:
                for data in chosen:
                    data.energy /= math.exp(self.rho_hi)
        self.assertEqual(images[2].shape, images[0].shape)
        return images + [brighter]

    def compare(self, cycles, cycles_again, pov, pov_brighter, what):
        blocks = [block_means(x) for x in (cycles, cycles_again, pov)]
        brighter = [block_means(x) for x in pov_brighter]
        floor = 0.004  # linear luminance below which blocks are black to the eye (8-bit sRGB 12)
        y = [luminance(b) + floor for b in blocks]
        ratio = np.log(y[2] / y[0])
        noise = np.abs(np.log(y[1] / y[0])).max()
        m = 3 * noise + 0.1
        lo, hi = -(self.rho_hi + m), m
        median = float(np.median(ratio))
        median_lo, median_hi = -(self.rho_hi + 3 * noise), -self.rho_lo + 3 * noise + 0.05
        hue = [hue_and_chroma(b) for b in blocks]
        coloured = (hue[0][1] > 0.15) & (hue[2][1] > 0.15)
        self.assertGreater(coloured.sum(), 16, "too few coloured blocks to compare hues")

        def turn(a, b):
            return np.degrees(np.abs(np.angle(np.exp(1j * (a - b)))))[coloured]
        dh = turn(hue[2][0], hue[0][0])
        excess = max(turn(hue_and_chroma(b)[0], hue[2][0]).max() for b in brighter)
        hue_tolerance = 3 * turn(hue[1][0], hue[0][0]).max() + excess + 2.0
        print(f"{what}: log luminance POV-Ray / Cycles median {median:+.3f} (allowed {median_lo:+.3f} .. "
              f"{median_hi:+.3f}), blocks {ratio.min():+.3f} .. {ratio.max():+.3f} (allowed {lo:+.3f} .. {hi:+.3f}); "
              f"hue over {coloured.sum()} blocks up to {dh.max():.1f} deg (allowed {hue_tolerance:.1f})", flush=True)
        self.assertTrue(median_lo <= median <= median_hi, f"{what}: median log ratio {median:+.3f}")
        bad = np.argwhere((ratio < lo) | (ratio > hi))
        self.assertEqual(len(bad), 0, f"{what}: blocks (row, column) out of [{lo:+.3f}, {hi:+.3f}]: "
                         f"{[(int(r), int(c), round(float(ratio[r, c]), 3)) for r, c in bad]}")
        worst = tuple(int(i) for i in np.argwhere(coloured)[int(np.argmax(dh))])
        self.assertLessEqual(dh.max(), hue_tolerance, f"{what}: hue turned by {dh.max():.1f} degrees in block {worst}: "
                             f"Cycles {blocks[0][worst]}, POV-Ray {blocks[2][worst]}")

    def terrain(self, **kw):
        args = dict(levels=6, seed=13)
        args.update(kw)
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(**args), {"FINISHED"})
        return bpy.context.active_object

    def test_default_point_light(self):
        terrain = self.terrain()
        self.factory("LIGHT")
        self.factory("CAMERA")
        self.compare(*self.renders(terrain), "default point light")

    def test_sun_and_sky(self):
        terrain = self.terrain()
        self.factory("CAMERA")
        bpy.ops.object.light_add(type="SUN", rotation=(0.7, 0.15, 2.2))
        sun = bpy.context.active_object.data
        sun.energy, sun.color = 3.0, (1.0, 0.85, 0.65)
        bpy.context.scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.25, 0.32, 0.5, 1)
        self.compare(*self.renders(terrain), "sun and sky")

    def test_spot_and_area_lights(self):
        terrain = self.terrain()
        self.factory("CAMERA")
        bpy.ops.object.light_add(type="SPOT", location=(3.0, -3.0, 6.0), rotation=(0.55, 0.0, 0.8))
        spot = bpy.context.active_object.data
        spot.energy, spot.color, spot.spot_size, spot.spot_blend = 3000.0, (1.0, 0.8, 0.6), math.radians(50), 0.3
        bpy.ops.object.light_add(type="AREA", location=(-2.0, 1.0, 7.0), rotation=(0.2, -0.25, 0.0))
        area = bpy.context.active_object.data
        area.energy, area.shape, area.size, area.size_y = 2000.0, "RECTANGLE", 2.0, 1.0
        area.color = (0.7, 0.85, 1.0)
        self.compare(*self.renders(terrain), "spot and area lights")

    def test_rivers_lakes_and_sea(self):
        terrain = self.terrain(erode_preset="VALLEYS", sea="FRACTION", sea_fraction=0.45)
        terrain.fracterra_terrain.rivers_width_coefficient = 0.08  # rivers a pixel or two wide at 160 x 90
        self.assertEqual(bpy.ops.object.fracterra_rivers(), {"FINISHED"})
        kinds = {c.get("fracterra_kind") for c in terrain.children}
        self.assertTrue({"RIVERS", "SEA"} <= kinds, kinds)
        bpy.ops.object.camera_add(location=(0.0, -11.0, 7.0), rotation=(1.0, 0.0, 0.0))
        bpy.context.scene.camera = bpy.context.active_object
        bpy.ops.object.light_add(type="SUN", rotation=(0.6, 0.2, 0.9))
        bpy.context.active_object.data.energy = 3.0
        bpy.context.scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.3, 0.35, 0.45, 1)
        self.compare(*self.renders(terrain), "rivers, lakes and sea")

if __name__ == "__main__":
    addon_harness.run(globals())
