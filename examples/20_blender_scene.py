"""Headless Blender demo: a fractal terrain scene, saved and rendered.

    blender -b --factory-startup --python examples/20_blender_scene.py -- --out demo-out/blender

Builds a terrain with the fracterra add-on (installed, or straight from this
source tree with the library from build/native), gives it a height-graded
material, a sea plane, a sun and a camera, saves scene.blend and renders
preview.png with Cycles (small and few samples: seconds on a CPU). Exits
non-zero with a message on any error.
"""

import argparse
import math
import os
import sys
import time
from pathlib import Path

import bpy
from mathutils import Vector

ROOT = Path(__file__).resolve().parent.parent


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="20_blender_scene.py", description=__doc__.split("\n\n")[0])
    p.add_argument("--out", required=True, help="output folder (created)")
    p.add_argument("--method", default="MIDPOINT", choices=["MIDPOINT", "ADDITIONS", "FBM", "SPECTRAL", "INTERPOLATED"],
                   help="terrain method (default MIDPOINT)")
    p.add_argument("--levels", type=int, default=8, help="grid is 2^levels + 1 per side, 1..13 (default 8)")
    p.add_argument("--hurst", type=float, default=0.8, help="Hurst exponent H in [0, 1] (default 0.8)")
    p.add_argument("--sigma", type=float, default=1.5, help="vertical scale in metres, > 0 (default 1.5)")
    p.add_argument("--seed", type=int, default=7, help="random seed, 0..2^31-1 (default 7)")
    p.add_argument("--size", type=float, default=20.0, help="terrain extent in metres (default 20)")
    p.add_argument("--sea-level", type=float, default=None, help="flatten below this height and add water")
    p.add_argument("--resolution", default="480x270", help="preview size WxH (default 480x270)")
    p.add_argument("--samples", type=int, default=16, help="Cycles samples (default 16)")
    p.add_argument("--engine", default="CYCLES", choices=["CYCLES", "BLENDER_EEVEE"],
                   help="renderer (default CYCLES: works without a GPU)")
    p.add_argument("--no-render", action="store_true", help="only build and save the scene")
    p.add_argument("--library", help="libfracterra.so to use when the add-on is run from the source tree")
    args = p.parse_args(argv)
    # Blender clamps operator properties silently; a script should refuse instead.
    if not 1 <= args.levels <= 13:
        p.error(f"--levels must be in 1..13, got {args.levels}")
    if not 0.0 <= args.hurst <= 1.0:
        p.error(f"--hurst must be in [0, 1], got {args.hurst}")
    if not args.sigma > 0:
        p.error(f"--sigma must be > 0, got {args.sigma}")
    if not args.size > 0:
        p.error(f"--size must be > 0, got {args.size}")
    return args


def enable_addon(library):
    """The installed add-on if there is one, else the source tree's copy."""
    import addon_utils
    source = "installed add-on"
    if not any(m.__name__ == "fracterra" for m in addon_utils.modules()):
        lib = library or os.environ.get("FRACTERRA_LIBRARY") or str(ROOT / "build" / "native" / "libfracterra.so")
        os.environ["FRACTERRA_LIBRARY"] = lib
        sys.path.insert(0, str(ROOT / "blender_addon"))  # enable() imports it from sys.path
        source = f"source tree with {lib}"
    if addon_utils.enable("fracterra", default_set=True, handle_error=None) is None:
        raise RuntimeError("could not enable the fracterra add-on")
    return source


def terrain_material():
    """Green lowlands, brown slopes, white tops: colour by object-space height."""
    mat = bpy.data.materials.new("Fractal Terrain")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    coords = nodes.new("ShaderNodeTexCoord")
    xyz = nodes.new("ShaderNodeSeparateXYZ")
    span = nodes.new("ShaderNodeMapRange")
    span.name = "Height Range"
    ramp = nodes.new("ShaderNodeValToRGB")
    stops = ((0.0, (0.10, 0.22, 0.06, 1)), (0.45, (0.33, 0.27, 0.16, 1)), (0.8, (0.45, 0.42, 0.40, 1)),
             (0.92, (0.95, 0.95, 0.97, 1)))
    ramp.color_ramp.elements[0].position, ramp.color_ramp.elements[0].color = stops[0]
    ramp.color_ramp.elements[1].position, ramp.color_ramp.elements[1].color = stops[1]
    for pos, color in stops[2:]:
        e = ramp.color_ramp.elements.new(pos)
        e.color = color
    links.new(coords.outputs["Object"], xyz.inputs["Vector"])
    links.new(xyz.outputs["Z"], span.inputs["Value"])
    links.new(span.outputs["Result"], ramp.inputs["Fac"])
    links.new(ramp.outputs["Color"], bsdf.inputs["Base Color"])
    bsdf.inputs["Roughness"].default_value = 0.9
    return mat


def water(size, level):
    bpy.ops.mesh.primitive_plane_add(size=size, location=(0, 0, level + 1e-3))
    plane = bpy.context.active_object
    plane.name = "Sea"
    mat = bpy.data.materials.new("Sea")
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.02, 0.12, 0.25, 1)
    bsdf.inputs["Roughness"].default_value = 0.05
    plane.data.materials.append(mat)
    return plane


def look_at(obj, target):
    obj.rotation_euler = (Vector(target) - obj.location).to_track_quat("-Z", "Y").to_euler()


def main():
    args = parse_args()
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    source = enable_addon(args.library)
    import fracterra.core as core
    ok, status = core.status()
    if not ok:
        raise RuntimeError(status)
    print(f"20_blender_scene: {status} ({source})")

    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    t0 = time.perf_counter()
    kw = dict(method=args.method, levels=args.levels, hurst=args.hurst, sigma=args.sigma, seed=args.seed,
              world_size=args.size, width=2 ** args.levels + 1, height=2 ** args.levels + 1,
              location=(0, 0, 0))
    if args.sea_level is not None:
        kw.update(use_sea_level=True, sea_level=args.sea_level)
    bpy.ops.mesh.fracterra_terrain_add(**kw)
    terrain = bpy.context.active_object
    print(f"20_blender_scene: terrain {len(terrain.data.vertices)} vertices in {time.perf_counter() - t0:.2f} s")
    mat = terrain_material()
    zs = [v.co.z for v in terrain.data.vertices]
    span = mat.node_tree.nodes["Height Range"]
    span.inputs["From Min"].default_value, span.inputs["From Max"].default_value = min(zs), max(zs)
    terrain.data.materials.append(mat)
    if args.sea_level is not None:
        water(args.size, args.sea_level)

    scene = bpy.context.scene
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(50), 0, math.radians(35)))
    bpy.context.active_object.data.energy = 4.0
    bpy.ops.object.camera_add(location=(0.0, -1.35 * args.size, 0.75 * args.size))
    camera = bpy.context.active_object
    look_at(camera, (0, 0, 0.5 * (min(zs) + max(zs)) - 0.1 * args.size))
    scene.camera = camera
    world = scene.world or bpy.data.worlds.new("World")
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.35, 0.5, 0.75, 1)

    blend = out / "scene.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(blend), check_existing=False)
    print(f"20_blender_scene: wrote {blend}")
    if not args.no_render:
        w, h = (int(v) for v in args.resolution.lower().split("x"))
        scene.render.engine = args.engine
        scene.render.resolution_x, scene.render.resolution_y = w, h
        scene.render.resolution_percentage = 100
        if args.engine == "CYCLES":
            scene.cycles.samples = args.samples
            scene.cycles.device = "CPU"
            scene.cycles.use_denoising = False
        scene.render.filepath = str(out / "preview.png")
        t0 = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        if not Path(scene.render.filepath).is_file():
            raise RuntimeError(f"the render did not write {scene.render.filepath}")
        print(f"20_blender_scene: rendered {scene.render.filepath} in {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a clear one-line message and a non-zero exit for scripts and CI
        import traceback
        traceback.print_exc()
        print(f"20_blender_scene: error: {e}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)
