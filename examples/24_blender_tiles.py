# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless Blender: a tile set imported as one mesh and as one object per tile,
at two levels of detail, rendered side by side to look for cracks and seams.

    blender -b --factory-startup --python examples/24_blender_tiles.py -- --out demo-out/tiles

Writes a 513^2 midpoint tile set of 4 x 4 tiles (the Dask driver's task run
in-process), imports it with File > Import > Tile Set (import_scene.
fracterra_tiles) four times (one mesh / one object per tile, lod 0 / lod 2),
renders each with Cycles, close above the middle of the set where four
tiles meet, under a sun that shows every shading discontinuity, and tiles the
four renders into tiles-blender.png (top: one mesh; bottom: one object per
tile; left lod 0, right lod 2). docs/scale.md shows it.
"""

import importlib.util
import math
import sys
from pathlib import Path

import bpy

ROOT = Path(__file__).resolve().parent.parent
SETTINGS = {"method": "MIDPOINT", "levels": 9, "hurst": 0.75, "seed": 7, "sigma": 1.0}
TILE = 128

_spec = importlib.util.spec_from_file_location("blender_scene_20", ROOT / "examples" / "20_blender_scene.py")
scene20 = importlib.util.module_from_spec(_spec)  # its enable_addon, shared by the Blender examples
_spec.loader.exec_module(scene20)


def parse_args():
    p = scene20.example_parser("24_blender_tiles.py", __doc__, "480x320", "each render's size")
    return scene20.parse_example(p)


def write_tileset(folder):
    from fracterra.core import tiles
    with tiles.TileSet.open(SETTINGS, folder, TILE) as ts:
        lo, hi = ts.height_range()
        cols, rows = ts.grid()
        for row in range(rows):
            for col in range(cols):
                if not ts.done(col, row):
                    ts.record(*tiles.write_tile(col, row, SETTINGS, None, TILE, "png16", lo, hi, str(folder)))
        ts.finish()


def clear_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)
    for coll in list(bpy.data.collections):
        bpy.data.collections.remove(coll)


def grey_material():
    mat = bpy.data.materials.get("tiles grey") or bpy.data.materials.new("tiles grey")
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.6, 0.6, 0.6, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.9
    bsdf.inputs["Specular"].default_value = 0.1
    return mat


def stage():
    scene = bpy.context.scene
    scene.render.film_transparent = False
    world = bpy.data.worlds.get("World") or bpy.data.worlds.new("World")
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.55, 0.65, 0.8, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.25
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    sun.data.energy = 4.0
    sun.data.angle = math.radians(0.5)
    # Low and across the tile edges: every normal jump at a seam shows as a line.
    sun.rotation_euler = (math.radians(60), 0.0, math.radians(30))
    scene.collection.objects.link(sun)
    cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    cam.data.lens = 50
    # Close above the middle of the set, where four tiles meet (x = 0, y = 0),
    # about 3 units across: a cell of lod 0 is some 3 pixels.
    cam.location = (0.0, -2.2, 3.2)
    cam.rotation_euler = (math.radians(34), 0.0, 0.0)
    scene.collection.objects.link(cam)
    scene.camera = cam


def render(folder, mode, lod, path, args):
    clear_scene()
    stage()
    result = bpy.ops.import_scene.fracterra_tiles(filepath=str(Path(folder) / "manifest.json"), lod=lod, mode=mode,
                                                  size=10.0)
    if result != {"FINISHED"}:
        raise RuntimeError(f"import failed: {result}")
    mat = grey_material()
    for obj in bpy.context.scene.objects:
        if obj.type == "MESH":
            obj.data.materials.append(mat)
    scene20.render_still(bpy.context.scene, args, path)


def montage(paths, out, w, h):
    """The four renders as 2 x 2 (row-major in `paths`), written to `out`."""
    import numpy as np
    big = np.zeros((2 * h, 2 * w, 4), dtype=np.float32)
    for k, p in enumerate(paths):
        img = bpy.data.images.load(str(p))
        px = np.array(img.pixels[:], dtype=np.float32).reshape(h, w, 4)  # bottom row first
        r, c = divmod(k, 2)
        big[(1 - r) * h:(2 - r) * h, c * w:(c + 1) * w] = px
        bpy.data.images.remove(img)
    big[:, w - 1:w + 1] = (1, 1, 1, 1)
    big[h - 1:h + 1, :] = (1, 1, 1, 1)
    m = bpy.data.images.new("montage", 2 * w, 2 * h, alpha=True)
    m.pixels = big.ravel()
    m.filepath_raw = str(out)
    m.file_format = "PNG"
    m.save()


def main():
    args = parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scene20.enable_addon(args.library)
    folder = out / "set"
    write_tileset(folder)
    paths = []
    for mode in ("MESH", "TILES"):
        for lod in (0, 2):
            p = out / f"tiles-{mode.lower()}-lod{lod}.png"
            render(folder, mode, lod, p, args)
            paths.append(p)
            print(f"rendered {p}")
    montage(paths, out / "tiles-blender.png", args.width, args.height)
    print(f"wrote {out / 'tiles-blender.png'}")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a script: one line, non-zero exit
        print(f"24_blender_tiles.py: error: {e}", file=sys.stderr)
        sys.exit(1)
