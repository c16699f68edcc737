# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: the add-on's default terrain and every terrain preset, rendered
one by one, beside A.N.T. Landscape's default (Blender's bundled add-on), and
the default shaped by a custom falloff mask from an object and from an image.

    blender -b --factory-startup --python examples/22_blender_presets.py -- --out docs/images/presets

Each terrain is added the way the redo panel's preset menu does it: the
operator's defaults, then the preset file's assignments. It gets the material
by height and slope, the sky and the sun of example 20 and a camera framed on
its own size, and is rendered with Cycles to <out>/<name>.png; a flat sea
plane is added where the preset has a sea. The masks: mask-object.png, the
outline of a wavy polygon (an n-gon 1 above the ground, faded inward over a
falloff width of 0.25); mask-image.png, a generated image of two soft blobs
(two islands in a sea at 0.3). Exits non-zero on any error.
"""

import importlib.util
import math
import sys
import time
from pathlib import Path

import bpy
import numpy as np

HERE = Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location("blender_scene_20", HERE / "20_blender_scene.py")
scene20 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scene20)
PRESETS = HERE.parent / "blender_addon" / "fracterra" / "presets" / "operator" / "mesh.fracterra_terrain_add"


def parse_args():
    p = scene20.example_parser("22_blender_presets.py", __doc__, "480x300")
    p.add_argument("--max-levels", type=int, default=9, help="cap on a preset's levels, and on its samples at 2^cap + 1 (smaller: faster)")
    p.add_argument("--only", default="", help="comma-separated names to render (default: all)")
    p.add_argument("--no-ant", action="store_true", help="skip A.N.T. Landscape's default")
    return scene20.parse_example(p)


def preset_values(path):
    """{property: value} that a preset file assigns (run against a recorder)."""
    class Recorder:
        pass
    op = Recorder()
    body = path.read_text().replace("op = bpy.context.active_operator", "")
    exec(compile(body, str(path), "exec"), {"bpy": bpy, "op": op})
    return dict(vars(op))


def clear():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def frame_and_render(obj, size, sea, args, path, material):
    """Sun, sky and a camera on `obj` (extent `size`), then a Cycles render to `path`."""
    obj.data.materials.clear()
    obj.data.materials.append(material)
    zs = [v.co.z for v in obj.data.vertices]
    if sea is not None:
        scene20.water(1.6 * size, sea)
    scene20.sun_camera_render(args, path, size, zs, back=1.35, up=0.75, lens=35, target_y=0.05)
    return min(zs), max(zs)


def mask_object():
    """A wavy n-gon over the default terrain's footprint: its outline shapes the land."""
    t = np.linspace(0, 2 * math.pi, 96, endpoint=False)
    r = 3.3 * (1 + 0.22 * np.sin(3 * t) + 0.1 * np.cos(5 * t + 1))
    mesh = bpy.data.meshes.new("Outline")
    mesh.from_pydata([(float(x), float(y), 1.0) for x, y in zip(r * np.cos(t), 0.85 * r * np.sin(t))], [],
                     [tuple(range(len(t)))])
    outline = bpy.data.objects.new("Outline", mesh)
    bpy.context.scene.collection.objects.link(outline)
    return {"falloff_mask_source": "OBJECT", "falloff_mask_object": outline.name, "falloff_width": 0.25}


def mask_image():
    """A 256^2 image of two soft blobs (white: land kept), row 0 the terrain's -y edge."""
    n = 256
    u = np.linspace(-1, 1, n)
    x, y = np.meshgrid(u, u)
    blobs = np.exp(-((x + 0.35) ** 2 + (y + 0.2) ** 2) / 0.12) + 0.8 * np.exp(-((x - 0.45) ** 2 + (y - 0.35) ** 2) / 0.06)
    m = np.clip(1.3 * blobs, 0, 1)
    image = bpy.data.images.new("Two Islands", n, n)
    px = np.ones((n, n, 4), dtype=np.float32)
    px[:, :, 0] = px[:, :, 1] = px[:, :, 2] = m
    image.pixels.foreach_set(px.ravel())
    return {"falloff_mask_source": "IMAGE", "falloff_mask_image": image.name, "sea": "HEIGHT", "sea_level": 0.3}


def main():
    args = parse_args()
    out = Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    print(f"22_blender_presets: {scene20.enable_addon(args.library)}")
    only = {n.strip() for n in args.only.split(",") if n.strip()}
    material = scene20.terrain_material()
    jobs = [("Default", {})] + [(p.stem, preset_values(p)) for p in sorted(PRESETS.glob("*.py"))]
    for name, values in jobs:
        if only and name not in only:
            continue
        clear()
        values = dict(values)
        if "levels" in values:
            values["levels"] = min(values["levels"], args.max_levels)
        for key in ("width", "height"):  # the same cap for the other methods' samples
            if key in values:
                values[key] = min(values[key], 2 ** args.max_levels + 1)
        t0 = time.perf_counter()
        result = bpy.ops.mesh.fracterra_terrain_add(location=(0, 0, 0), **values)
        if result != {"FINISHED"}:
            raise RuntimeError(f"{name}: the terrain operator returned {result}")
        obj = bpy.context.active_object
        s = obj.fracterra_terrain
        sea = None
        if s.sea == "HEIGHT":
            sea = s.sea_level
        elif s.sea == "FRACTION":
            sea = min(v.co.z for v in obj.data.vertices)
        size = s.world_size
        slug = name.lower().replace(" ", "-")
        lo, hi = frame_and_render(obj, size, sea, args, out / f"{slug}.png", material)
        print(f"22_blender_presets: {name}: relief {hi - lo:.2f} over {size:g} ({(hi - lo) / size:.2f}), "
              f"{time.perf_counter() - t0:.1f} s -> {out / slug}.png")
    for name, make in (("Mask Object", mask_object), ("Mask Image", mask_image)):
        if only and name not in only:
            continue
        clear()
        values = {"levels": min(9, args.max_levels), "falloff": "CUSTOM", **make()}
        result = bpy.ops.mesh.fracterra_terrain_add(location=(0, 0, 0), **values)
        if result != {"FINISHED"}:
            raise RuntimeError(f"{name}: the terrain operator returned {result}")
        obj = bpy.context.active_object
        s = obj.fracterra_terrain
        sea = s.sea_level if s.sea == "HEIGHT" else None
        for other in bpy.data.objects:  # the mask object is not in the picture
            if other != obj:
                other.hide_render = True
        slug = name.lower().replace(" ", "-")
        frame_and_render(obj, s.world_size, sea, args, out / f"{slug}.png", material)
        print(f"22_blender_presets: {name} -> {out / slug}.png")
    if not args.no_ant and (not only or "ANT" in only):
        import addon_utils
        clear()
        addon_utils.enable("ant_landscape", default_set=True)
        bpy.ops.mesh.landscape_add(refresh=True)  # A.N.T.'s own defaults (refresh: it runs only then)
        obj = bpy.context.active_object
        n = len(obj.data.vertices)
        side = math.isqrt(n)
        if side * side == n:  # its grid gets the same height and slope attributes, for the same material
            from fracterra.blender.build import mesh as mesh_build
            from fracterra.core.grid import height_slope
            co = mesh_build.array.array("f", [0.0]) * (3 * n)
            obj.data.vertices.foreach_get("co", co)
            mesh_build.set_height_slope(obj.data, *height_slope(co, side, side))
        xs = [v.co.x for v in obj.data.vertices]
        size = max(xs) - min(xs)
        lo, hi = frame_and_render(obj, size, None, args, out / "ant-landscape-default.png", material)
        print(f"22_blender_presets: A.N.T. default: relief {hi - lo:.2f} over {size:g} ({(hi - lo) / size:.2f})")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:
        import os
        import traceback
        traceback.print_exc()
        print(f"22_blender_presets: error: {e}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)
