# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: a fractal terrain before and after the add-on's Erode step.

    blender -b --factory-startup --python examples/23_blender_erosion.py -- --out OUT [--size 257]

Adds the same fBm terrain twice with the fracterra add-on (installed, or from
this source tree with the library from build/native): once as generated, once
with the Erode preset "Land" (rivers, rain, scree). Both get the add-on's
terrain material, which shows the library's splat colours (rock on slopes,
grass and snow by height, and on the eroded one sediment in channels and
deposits). Renders before-after.png with Cycles and saves
erosion.blend. Exits non-zero with a message on any error.
"""

import importlib.util
import math
import sys
from pathlib import Path

import bpy

ROOT = Path(__file__).resolve().parent.parent

_spec = importlib.util.spec_from_file_location("blender_scene_20", ROOT / "examples" / "20_blender_scene.py")
scene20 = importlib.util.module_from_spec(_spec)  # its enable_addon, shared by the Blender examples
_spec.loader.exec_module(scene20)


def parse_args():
    p = scene20.example_parser("23_blender_erosion.py", __doc__, "960x400")
    p.add_argument("--size", type=int, default=257, help="vertices per side (default 257)")
    return scene20.parse_example(p)


def terrain(args, x, erode):
    # The terrain of examples/14_eroded_terrain.sh (fBm, H = 0.8, seed 7, 10 units).
    result = bpy.ops.mesh.fracterra_terrain_add(method="FBM", width=args.size, height=args.size, hurst=0.8,
                                                seed=7, world_size=10.0, erode_preset=erode,
                                                location=(x, 0.0, 0.0))
    if result != {"FINISHED"}:
        raise RuntimeError(f"terrain add failed: {result}")
    return bpy.context.active_object


def main():
    args = parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scene20.enable_addon(args.library)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    before = terrain(args, -5.6, "NONE")
    after = terrain(args, 5.6, "LAND")
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(50), 0.0, math.radians(130)))
    bpy.context.active_object.data.energy = 4.0
    bpy.ops.object.camera_add(location=(0.0, -15.0, 13.0), rotation=(math.radians(47), 0.0, 0.0))
    camera = bpy.context.active_object
    camera.data.lens = 30
    scene = bpy.context.scene
    scene.camera = camera
    world = bpy.data.worlds.new("Sky") if scene.world is None else scene.world
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.45, 0.6, 0.85, 1)
    scene20.render_still(scene, args, out / "before-after.png")
    bpy.ops.wm.save_as_mainfile(filepath=str(out / "erosion.blend"))
    print(f"wrote {out / 'before-after.png'} and {out / 'erosion.blend'}")


try:
    main()
except Exception as e:  # noqa: BLE001 - a script run by blender -b must exit non-zero
    print(f"23_blender_erosion.py: {e}", file=sys.stderr)
    sys.exit(1)
