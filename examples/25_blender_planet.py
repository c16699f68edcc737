# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: a fractal planet with its sea, rendered from space.

    blender -b --factory-startup --python examples/25_blender_planet.py -- --out demo-out/planet

Adds a planet with Add > Mesh > Fractal Planet (the add-on's defaults: level
8, radius 1 m, heights x 20, a sea over 70 % of the area, snow above a line
that falls towards the poles), a sun from the side, a black sky and a camera
looking at the globe from --view-latitude; saves scene.blend and renders
preview.png with Cycles. docs/images/planet-blender.png is

    ... -- --out demo-out/planet --seed 24 --resolution 640x640 --samples 48

(seed 24 has land round the north pole). Exits non-zero with a message on any error.
"""

import importlib.util
import math
import sys
import time
from pathlib import Path

import bpy
from mathutils import Vector

HERE = Path(__file__).resolve().parent
# The add-on set-up and the render of the general example.
_spec = importlib.util.spec_from_file_location("blender_scene_20", HERE / "20_blender_scene.py")
scene20 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scene20)


def parse_args():
    p = scene20.example_parser("25_blender_planet.py", __doc__, "480x480")
    p.add_argument("--seed", type=int, default=24, help="the planet's seed (default 24)")
    p.add_argument("--level", type=int, default=8, help="cube-face level, 0..11 (default 8: 393 218 vertices)")
    p.add_argument("--view-latitude", type=float, default=45.0, help="the camera's latitude, degrees (default 45)")
    args = scene20.parse_example(p)
    if not -90 <= args.view_latitude <= 90:
        p.error(f"--view-latitude must be in -90..90, got {args.view_latitude}")
    return args


def toward(obj, direction):
    """Points `obj` (a camera or a sun: they look down their -Z) along `direction`."""
    obj.rotation_euler = Vector(direction).to_track_quat("-Z", "Y").to_euler()


def main():
    args = parse_args()
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    source = scene20.enable_addon(args.library)
    import fracterra.core as core
    ok, status = core.status()
    if not ok:
        raise RuntimeError(status)
    print(f"25_blender_planet: {status} ({source})")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)

    t0 = time.perf_counter()
    result = bpy.ops.mesh.fracterra_planet_add(seed=args.seed, level=args.level)
    if result != {"FINISHED"}:
        raise RuntimeError(f"Add Fractal Planet failed: {result}")
    planet = bpy.context.active_object
    print(f"25_blender_planet: {len(planet.data.vertices):,} vertices in {time.perf_counter() - t0:.1f} s")

    scene = bpy.context.scene
    lat = math.radians(args.view_latitude)
    eye = Vector((4.2 * math.cos(lat), 0.0, 4.2 * math.sin(lat)))  # the globe fills about 3/4 of the frame
    bpy.ops.object.camera_add(location=eye)
    camera = bpy.context.active_object
    toward(camera, -eye)
    scene.camera = camera
    bpy.ops.object.light_add(type="SUN")
    sun = bpy.context.active_object
    sun.data.energy = 4.0
    toward(sun, -Vector((math.cos(1.2), math.sin(1.2), 0.5)))  # from the right: a terminator on the left
    world = scene.world or bpy.data.worlds.new("World")
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.0, 0.0, 0.002, 1.0)

    blend = out / "scene.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(blend), check_existing=False)
    t0 = time.perf_counter()
    scene20.render_still(scene, args, out / "preview.png")
    print(f"25_blender_planet: wrote {blend} and rendered {scene.render.filepath} in "
          f"{time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a clear one-line message and a non-zero exit for scripts and CI
        print(f"25_blender_planet: error: {e}", file=sys.stderr)
        sys.exit(1)
