# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: one eroded terrain rendered in Blender and in POV-Ray,
coloured alike by the splat rules.

    blender -b --factory-startup --python examples/24_blender_splat_materials.py -- --out OUT [--rules R.json]

Adds an fBm terrain (257^2, H = 0.8, seed 7, 10 units) eroded by the Land
preset with the fracterra add-on (installed, or from this source tree with the
library from build/native). Its material reads the library's splat colour map
(the built-in rules, or --rules); a sun and a sky light it. Renders it with
Eevee (blender.png), exports the scene with File > Export > POV-Ray (fracterra)
and renders that with povray (povray.png), and puts the two side by side
(splat-materials.png). Exits non-zero with a message on any error.
"""

import importlib.util
import math
import sys
from pathlib import Path

import bpy
import numpy as np

ROOT = Path(__file__).resolve().parent.parent

_spec = importlib.util.spec_from_file_location("blender_scene_20", ROOT / "examples" / "20_blender_scene.py")
scene20 = importlib.util.module_from_spec(_spec)  # its enable_addon, shared by the Blender examples
_spec.loader.exec_module(scene20)


def parse_args():
    p = scene20.example_parser("24_blender_splat_materials.py", __doc__, "480x300")
    p.add_argument("--size", type=int, default=257, help="vertices per side (default 257)")
    p.add_argument("--rules", default="", help="splat rules JSON (default: the built-in rules)")
    return scene20.parse_example(p)


def pixels(path):
    """RGBA rows from the top, as stored (sRGB bytes / 255)."""
    image = bpy.data.images.load(str(path))
    w, h = image.size
    px = np.empty(w * h * 4, dtype=np.float32)
    image.pixels.foreach_get(px)
    bpy.data.images.remove(image)
    return px.reshape(h, w, 4)[::-1]


def side_by_side(left, right, path, gap=8):
    a, b = pixels(left), pixels(right)
    h, w = a.shape[:2]
    out = np.ones((h, 2 * w + gap, 4), dtype=np.float32)
    out[:, :w], out[:, w + gap:] = a, b
    image = bpy.data.images.new("side by side", 2 * w + gap, h)
    image.pixels.foreach_set(out[::-1].ravel())
    image.filepath_raw, image.file_format = str(path), "PNG"
    image.save()


def main():
    args = parse_args()
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    scene20.enable_addon(args.library)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    result = bpy.ops.mesh.fracterra_terrain_add(method="FBM", width=args.size, height=args.size, hurst=0.8, seed=7,
                                                world_size=10.0, erode_preset="LAND", splat_rules=args.rules)
    if result != {"FINISHED"}:
        raise RuntimeError(f"terrain add failed: {result}")
    terrain = bpy.context.active_object
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(50), 0.0, math.radians(130)))
    bpy.context.active_object.data.energy = 3.0
    bpy.ops.object.camera_add(location=(0.0, -11.5, 8.0), rotation=(math.radians(52), 0.0, 0.0))
    camera = bpy.context.active_object
    camera.data.lens = 30
    scene = bpy.context.scene
    scene.camera = camera
    world = bpy.data.worlds.new("Sky") if scene.world is None else scene.world
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.45, 0.6, 0.85, 1)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
    scene.view_settings.view_transform = "Standard"  # POV-Ray writes plain sRGB
    scene20.render_still(scene, args, out / "blender.png", engine="BLENDER_EEVEE")
    bpy.context.view_layer.objects.active = terrain
    pov = out / "scene.pov"
    result = bpy.ops.export_scene.fracterra_pov(filepath=str(pov), render=True, width=args.width,
                                                height=args.height)
    if result != {"FINISHED"}:
        raise RuntimeError(f"POV-Ray export failed: {result}")
    (out / "scene.png").replace(out / "povray.png")
    side_by_side(out / "blender.png", out / "povray.png", out / "splat-materials.png")
    print(f"wrote {out / 'splat-materials.png'} (Eevee left, POV-Ray right)")


try:
    main()
except Exception as e:  # noqa: BLE001 - a script run by blender -b must exit non-zero
    print(f"24_blender_splat_materials.py: {e}", file=sys.stderr)
    sys.exit(1)
