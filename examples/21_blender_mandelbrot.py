# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: the Mandelbrot set as a terrain, with its level curves.

    blender -b --factory-startup --python examples/21_blender_mandelbrot.py -- --out demo-out/mandelbrot

Adds a Mandelbrot terrain with the fracterra add-on (the set is the plateau,
the escape time's slopes fall away from it), a sea, and the curves of equal
escape time (equipotentials) as bevelled curves through the add-on's
coastline operator at the heights fracterra.core.mandelbrot_level_height
gives; saves scene.blend and renders preview.png with Cycles. Exits non-zero
with a message on any error.
"""

import importlib.util
import math
import sys
import time
from pathlib import Path

import bpy

HERE = Path(__file__).resolve().parent
# The add-on set-up, material, sea and camera aim of the general example.
_spec = importlib.util.spec_from_file_location("blender_scene_20", HERE / "20_blender_scene.py")
scene20 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scene20)


def parse_args():
    p = scene20.example_parser("21_blender_mandelbrot.py", __doc__, "640x480")
    p.add_argument("--samples-x", type=int, default=513, help="vertices along x, 2..8193 (default 513)")
    p.add_argument("--center", default="-0.65,0", help="centre of the view, X,Y (default -0.65,0)")
    p.add_argument("--zoom", type=float, default=0.85, help="the width spans 4 / zoom (default 0.85)")
    p.add_argument("--iterations", type=int, default=40, help="maximum iterations (default 40)")
    p.add_argument("--curves", default="2,2.5,3,4,5,6,8", help="escape times of the level curves")
    args = scene20.parse_example(p)
    try:
        args.cx, args.cy = (float(v) for v in args.center.split(","))
        args.levels = [float(v) for v in args.curves.split(",")]
    except ValueError:
        p.error("--center X,Y and --curves A,B,... take numbers")
    if not 2 <= args.samples_x <= 8193:
        p.error(f"--samples-x must be in 2..8193, got {args.samples_x}")
    return args


def main():
    args = parse_args()
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    source = scene20.enable_addon(args.library)
    import fracterra.core as core
    ok, status = core.status()
    if not ok:
        raise RuntimeError(status)
    print(f"21_blender_mandelbrot: {status} ({source})")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)

    size = 10.0
    nx = args.samples_x
    ny = max(2, round((nx - 1) * 0.75) + 1)
    settings = dict(method="MANDELBROT", width=nx, height=ny, center_x=args.cx, center_y=args.cy, zoom=args.zoom,
                    iterations=args.iterations, supersample=2, sigma=2.0, world_size=size,
                    levelling=0.0, height_offset=0.0, falloff="NONE")  # the set as it is: no landform
    t0 = time.perf_counter()
    bpy.ops.mesh.fracterra_terrain_add(location=(0, 0, 0), **settings)
    terrain = bpy.context.active_object
    print(f"21_blender_mandelbrot: terrain {len(terrain.data.vertices)} vertices in {time.perf_counter() - t0:.2f} s")
    mat = scene20.terrain_material()  # by the terrain's own height and slope attributes
    zs = [v.co.z for v in terrain.data.vertices]
    terrain.data.materials.clear()  # in place of the terrain's splat material
    terrain.data.materials.append(mat)

    # The sea at the equipotential of escape time 1.6, the curves above it.
    sea = core.mandelbrot_level_height(1.6, settings)
    scene20.water(3 * size, sea)
    tube = bpy.data.materials.new("Level Curves")
    tube.use_nodes = True
    bsdf = tube.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.9, 0.35, 0.05, 1)
    for nu in args.levels:
        bpy.context.view_layer.objects.active = terrain
        level = core.mandelbrot_level_height(nu, settings)
        result = bpy.ops.curve.fracterra_coastline_add(use_quantile=False, level=level, radius=0.035)
        if result != {"FINISHED"}:
            raise RuntimeError(f"the level curve of escape time {nu} failed: {result}")
        curve = bpy.context.active_object
        curve.name = f"Escape time {nu:g}"
        for spline in curve.data.splines:  # contour points carry radius 0, which scales the bevel to nothing
            spline.points.foreach_set("radius", [1.0] * len(spline.points))
        curve.location.z += 0.015  # sit on the surface rather than half inside it
        curve.data.materials.append(tube)

    scene = bpy.context.scene
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(50), 0, math.radians(35)))
    bpy.context.active_object.data.energy = 4.0
    bpy.ops.object.camera_add(location=(0.0, -1.25 * size, 0.75 * size))
    camera = bpy.context.active_object
    scene20.look_at(camera, (0, 0.02 * size, 0.5 * (min(zs) + max(zs))))
    scene.camera = camera
    world = scene.world or bpy.data.worlds.new("World")
    scene.world = world
    scene20.sky(world)

    blend = out / "scene.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(blend), check_existing=False)
    t0 = time.perf_counter()
    scene20.render_still(scene, args, out / "preview.png")
    print(f"21_blender_mandelbrot: wrote {blend} and rendered {scene.render.filepath} in "
          f"{time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a clear one-line message and a non-zero exit for scripts and CI
        print(f"21_blender_mandelbrot: error: {e}", file=sys.stderr)
        sys.exit(1)
