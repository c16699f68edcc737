# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender demo: a fractal terrain scene, saved and rendered.

    blender -b --factory-startup --python examples/20_blender_scene.py -- --out demo-out/blender

Builds a terrain with the fracterra add-on (installed, or straight from this
source tree with the library from build/native) in its splat material (the
library's colour map), eroded, with its rivers and lakes (Rivers and Lakes), a
sea plane, a sun, a sky and a camera, adds a branching fractal lightning bolt
and a river-like fractal polyline over it, saves scene.blend, renders
preview.png with Cycles (small and few samples: seconds on a CPU) and exports
the POV-Ray scene (scene.pov; --pov-render renders it with povray into
scene.png: the same scene, docs/povray.md).
Exits non-zero with a message on any error.
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


def example_parser(prog, doc, resolution, what="render size"):
    """The arguments every Blender example takes (--out, --resolution,
    --samples, --library); the example adds its own and calls parse_example."""
    p = argparse.ArgumentParser(prog=prog, description=doc.split("\n\n")[0])
    p.add_argument("--out", required=True, help="output folder (created)")
    p.add_argument("--resolution", default=resolution, help=f"{what} WxH (default {resolution})")
    p.add_argument("--samples", type=int, default=16, help="Cycles samples (default 16)")
    p.add_argument("--library", help="libfracterra.so to use when the add-on is run from the source tree")
    return p


def parse_example(p):
    """Parses what follows Blender's `--`; --resolution becomes args.width and args.height."""
    args = p.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
    try:
        args.width, args.height = (int(v) for v in args.resolution.lower().split("x"))
    except ValueError:
        p.error(f"--resolution must be WIDTHxHEIGHT, e.g. {p.get_default('resolution')}; got {args.resolution!r}")
    return args


def parse_args():
    p = example_parser("20_blender_scene.py", __doc__, "480x270", "preview size, also for --pov-render,")
    p.add_argument("--method", default="MIDPOINT", choices=["MIDPOINT", "ADDITIONS", "FBM", "SPECTRAL", "INTERPOLATED"],
                   help="terrain method (default MIDPOINT)")
    p.add_argument("--levels", type=int, default=8, help="grid is 2^levels + 1 per side, 1..13 (default 8)")
    p.add_argument("--hurst", type=float, default=0.8, help="Hurst exponent H in [0, 1] (default 0.8)")
    p.add_argument("--sigma", type=float, default=1.5, help="vertical scale in metres, > 0 (default 1.5)")
    p.add_argument("--seed", type=int, default=7, help="random seed, 0..2^31-1 (default 7)")
    p.add_argument("--size", type=float, default=20.0, help="terrain extent in metres (default 20)")
    p.add_argument("--sea-level", type=float, default=0.3,
                   help="flatten below this height and add water (default 0.3: the plain is under the sea)")
    p.add_argument("--erode", default="VALLEYS", choices=["NONE", "VALLEYS", "RAIN", "SCREE", "LAND", "BADLANDS"],
                   help="erosion preset after generating (default VALLEYS: Gentle Valleys; the sea is its base level)")
    p.add_argument("--no-rivers", action="store_true", help="no Rivers and Lakes on the terrain")
    p.add_argument("--engine", default="CYCLES", choices=["CYCLES", "BLENDER_EEVEE"],
                   help="renderer (default CYCLES: works without a GPU)")
    p.add_argument("--no-polylines", action="store_true", help="terrain only")
    p.add_argument("--no-render", action="store_true", help="do not render the Blender preview")
    p.add_argument("--no-pov", action="store_true", help="do not export the POV-Ray scene")
    p.add_argument("--pov-render", action="store_true", help="also render scene.pov with povray (pov.png)")
    args = parse_example(p)
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


def render_still(scene, args, path, engine="CYCLES"):
    """Renders the scene to `path` at --resolution (Cycles: --samples on the
    CPU, no denoising: Debian's Blender is built without OpenImageDenoise)."""
    scene.render.engine = engine
    scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
    scene.render.resolution_percentage = 100
    if engine == "CYCLES":
        scene.cycles.samples = args.samples
        scene.cycles.device = "CPU"
        scene.cycles.use_denoising = False
    scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    if not Path(path).is_file():
        raise RuntimeError(f"the render did not write {path}")


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
    """Green lowlands, brown slopes, white tops, bare rock where it is steep: by the
    terrain's own fracterra_height and fracterra_slope attributes (0..1), so it
    fits a terrain of any size and height."""
    mat = bpy.data.materials.new("Fractal Terrain")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    height, slope = nodes.new("ShaderNodeAttribute"), nodes.new("ShaderNodeAttribute")
    height.attribute_name, slope.attribute_name = "fracterra_height", "fracterra_slope"
    ramp = nodes.new("ShaderNodeValToRGB")
    stops = ((0.0, (0.10, 0.22, 0.06, 1)), (0.45, (0.33, 0.27, 0.16, 1)), (0.8, (0.45, 0.42, 0.40, 1)),
             (0.92, (0.95, 0.95, 0.97, 1)))
    ramp.color_ramp.elements[0].position, ramp.color_ramp.elements[0].color = stops[0]
    ramp.color_ramp.elements[1].position, ramp.color_ramp.elements[1].color = stops[1]
    for pos, color in stops[2:]:
        e = ramp.color_ramp.elements.new(pos)
        e.color = color
    steep = nodes.new("ShaderNodeMapRange")  # 0 below ~25 degrees, 1 above ~40
    steep.inputs["From Min"].default_value, steep.inputs["From Max"].default_value = 0.28, 0.45
    rock = nodes.new("ShaderNodeMixRGB")
    rock.inputs["Color2"].default_value = (0.23, 0.21, 0.19, 1)
    links.new(height.outputs["Fac"], ramp.inputs["Fac"])
    links.new(slope.outputs["Fac"], steep.inputs["Value"])
    links.new(steep.outputs["Result"], rock.inputs["Fac"])
    links.new(ramp.outputs["Color"], rock.inputs["Color1"])
    links.new(rock.outputs["Color"], bsdf.inputs["Base Color"])
    bsdf.inputs["Roughness"].default_value = 0.9
    return mat


def sky(world):
    """Seen by the camera, a sky that pales from blue at the top of the frame to
    haze at the bottom (the camera looks down on the terrain, so a physical sky
    would show its black below-horizon half); as light, a uniform blue sky
    beside the sun lamp. Much less flat than one uniform background."""
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    coords, xyz, ramp = nodes.new("ShaderNodeTexCoord"), nodes.new("ShaderNodeSeparateXYZ"), nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].color = (0.78, 0.84, 0.92, 1)  # haze
    ramp.color_ramp.elements[1].color = (0.22, 0.42, 0.78, 1)  # zenith blue
    path, mix = nodes.new("ShaderNodeLightPath"), nodes.new("ShaderNodeMixRGB")
    mix.inputs["Color1"].default_value = (0.40, 0.55, 0.80, 1)  # what the terrain is lit by
    links.new(coords.outputs["Window"], xyz.inputs["Vector"])
    links.new(xyz.outputs["Y"], ramp.inputs["Fac"])
    links.new(path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    links.new(ramp.outputs["Color"], mix.inputs["Color2"])
    background = nodes["Background"]
    background.inputs["Strength"].default_value = 1.0
    links.new(mix.outputs["Color"], background.inputs["Color"])


def even_sky(world, color):
    """A sky of one colour: what the camera sees behind the terrain and what lights it, so the
    POV-Ray export's background and ambient light are this colour too."""
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*color, 1.0)
    background.inputs["Strength"].default_value = 1.0


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


def add_polylines(args, top):
    """A branching lightning bolt from the sky and a winding line across the terrain."""
    glow = bpy.data.materials.new("Lightning")
    glow.use_nodes = True
    nodes = glow.node_tree.nodes
    nodes.remove(nodes["Principled BSDF"])
    emit = nodes.new("ShaderNodeEmission")
    emit.inputs["Color"].default_value = (0.6, 0.75, 1.0, 1)
    emit.inputs["Strength"].default_value = 30.0
    glow.node_tree.links.new(emit.outputs["Emission"], nodes["Material Output"].inputs["Surface"])
    s = args.size
    bpy.ops.curve.fracterra_polyline_add(method="FPL3D", start=(0.15 * s, 0.25 * s, top + 0.3 * s),
                                         end=(0.1 * s, 0.15 * s, top), depth=9, spread=0.12, seed=args.seed,
                                         branch_prob=0.6, radius=0.004 * s)
    bolt = bpy.context.active_object
    bolt.name = "Lightning"
    bolt.data.materials.append(glow)
    bpy.ops.curve.fracterra_polyline_add(method="FPL", start=(-0.45 * s, -0.3 * s, top + 0.05 * s),
                                         end=(0.45 * s, 0.1 * s, top + 0.05 * s), depth=8, spread=0.25,
                                         seed=args.seed + 1, radius=0.003 * s)
    bpy.context.active_object.name = "Horizon Line"


def sun_camera_render(args, path, size, zs, back, up, lens, target_y):
    """A sun from the south-west, a camera `back` x size south of the centre
    and `up` x size above the top, looking at the middle of the relief `zs`
    (`target_y` x size north), the sky; renders the still to `path`."""
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(50), 0, math.radians(35)))
    bpy.context.active_object.data.energy = 4.0
    bpy.context.active_object.data.angle = math.radians(2)
    bpy.ops.object.camera_add(location=(0.0, -back * size, up * size + max(zs)))
    camera = bpy.context.active_object
    camera.data.lens = lens
    look_at(camera, (0, target_y * size, 0.5 * (min(zs) + max(zs))))
    scene = bpy.context.scene
    scene.camera = camera
    scene.world = scene.world or bpy.data.worlds.new("World")
    sky(scene.world)
    render_still(scene, args, path)


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
    # The demo's terrain is the add-on's default landform (a mountain falling
    # to a plain), with the sea over the plain: an island, as in the POV-Ray demo.
    if args.sea_level is not None:
        kw.update(sea="HEIGHT", sea_level=args.sea_level)
    bpy.ops.mesh.fracterra_terrain_add(erode_preset=args.erode, **kw)
    terrain = bpy.context.active_object
    if not args.no_rivers:
        # Rivers as curves as wide as their discharge, lakes as water at their
        # levels, all parented to the terrain (stored with it: Regenerate
        # retraces them). Wider than the library's default width coefficient
        # (0.03 world units), so that they read at the preview's size.
        terrain.fracterra_terrain.rivers_width_coefficient = 0.08
        result = bpy.ops.object.fracterra_rivers()
        if result != {"FINISHED"}:
            raise RuntimeError(f"Rivers and Lakes: {result}")
        bpy.context.view_layer.objects.active = terrain
    print(f"20_blender_scene: terrain {len(terrain.data.vertices)} vertices in {time.perf_counter() - t0:.2f} s")
    zs = [v.co.z for v in terrain.data.vertices]
    if args.sea_level is not None:
        water(args.size, args.sea_level)
        bpy.context.view_layer.objects.active = terrain
        bpy.ops.curve.fracterra_coastline_add(use_quantile=False, level=args.sea_level + 1e-3,
                                              radius=0.002 * args.size)
        bpy.context.view_layer.objects.active = terrain

    if not args.no_polylines:
        add_polylines(args, max(zs))

    scene = bpy.context.scene
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(50), 0, math.radians(35)))
    bpy.context.active_object.data.energy = 4.0
    bpy.context.active_object.data.angle = math.radians(2)  # soft shadow edges
    bpy.ops.object.camera_add(location=(0.0, -1.5 * args.size, 0.8 * args.size))
    camera = bpy.context.active_object
    look_at(camera, (0, 0.05 * args.size, 0.5 * (min(zs) + max(zs))))
    scene.camera = camera
    world = scene.world or bpy.data.worlds.new("World")
    scene.world = world
    even_sky(world, (0.42, 0.56, 0.80))
    scene.view_settings.view_transform = "Standard"  # plain sRGB, as POV-Ray writes (Filmic would tone it)

    blend = out / "scene.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(blend), check_existing=False)
    print(f"20_blender_scene: wrote {blend}")
    w, h = args.width, args.height
    if not args.no_render:
        t0 = time.perf_counter()
        render_still(scene, args, out / "preview.png", args.engine)
        print(f"20_blender_scene: rendered {out / 'preview.png'} in {time.perf_counter() - t0:.1f} s")
    if not args.no_pov:
        bpy.context.view_layer.objects.active = terrain
        pov = out / "scene.pov"
        result = bpy.ops.export_scene.fracterra_pov(filepath=str(pov), render=args.pov_render,
                                                    width=w, height=h)
        if result != {"FINISHED"}:
            raise RuntimeError(f"POV-Ray export returned {result}")
        print(f"20_blender_scene: wrote {pov}" + (f" and {out / 'scene.png'}" if args.pov_render else ""))


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a clear one-line message and a non-zero exit for scripts and CI
        import traceback
        traceback.print_exc()
        print(f"20_blender_scene: error: {e}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)
