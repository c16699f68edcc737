# SPDX-License-Identifier: GPL-3.0-or-later
"""The Blender pictures of docs/erosion.md, taken in the real GUI the way a user
makes them: Add > Fractal Terrain from the menu (a background job), the
sidebar's settings (each edit its own undo step, as the UI pushes it),
Regenerate and Build Final as their buttons run them. Screenshots of the 3D
view (solid shading with cavity), cropped and paired side by side:

  erosion-blender-before-after.png   the default mountain, then Rugged Mountains
  erosion-blender-preview-final.png  Detail Levels 10 with Auto Update (Preview), then Build Final
  erosion-blender-mask.png           a vertex group over the left half as the Mask, Advanced open
  erosion-sea-blender.png            fBm 513^2, seed 7, no falloff, Sea Fraction 0.3, then Rugged Mountains

Prints what the sidebar holds and the mesh is after each step ("PIC ..."). With
--tryout it goes on as a new user would: Ctrl+Z twice and Ctrl+Shift+Z twice
(keys), Esc during a levels-12 Regenerate, a second Add. Run under Xvfb:

    xvfb-run -a -s "-screen 0 1280x800x24" env BLENDER_USER_SCRIPTS=/tmp/us \\
        blender --factory-startup --window-geometry 0 0 1280 800 \\
        --python scripts/blender_erosion_pictures.py -- --zip build/blender_addon/fracterra.zip \\
        --out docs/images [--tryout]

(xdotool must be installed: the splash screen, the sidebar's tab and the keys.)
Exits 0 when every step ran (gui_harness.run_in_event_loop).
"""

import argparse
import math
import os
import subprocess
import sys
import time

import bpy
import numpy as np
from mathutils import Euler, Vector

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "blender"))
import addon_harness  # noqa: E402
import gui_harness  # noqa: E402
from gui_harness import in_view3d, view3d  # noqa: E402

STEP = 0.5  # seconds between steps: Blender redraws in between
MOUNTAIN_VIEW = dict(distance=14.0, elevation=58, azimuth=-30, target=(0.3, 0.3, 0.4))
SEA_VIEW = dict(distance=20.0, elevation=50, azimuth=-40, target=(0.0, 0.0, 1.0))
# Crops of the 1280 x 800 window (left, top, right, bottom) and their scale.
MOUNTAIN_CROP, MOUNTAIN_SCALE = (200, 262, 835, 718), 0.75
SEA_CROP = (255, 225, 835, 615)
MASK_CROP = (180, 75, 1030, 615)  # the view and the sidebar's Erosion box


def options():
    p = argparse.ArgumentParser()
    p.add_argument("--zip", required=True)
    p.add_argument("--out", required=True, help="folder for the pictures (and the raw screenshots in raw/)")
    p.add_argument("--tryout", action="store_true", help="then undo, Esc during a levels-12 build, a second Add")
    return p.parse_args(sys.argv[sys.argv.index("--") + 1:])


ARGS = options()
RAW = os.path.join(ARGS.out, "raw")


def log(*a):
    print("PIC", " ".join(str(x) for x in a), flush=True)


def xdotool(*a):
    subprocess.run(["xdotool", *a], check=False)


def pointer_to_view():
    window, _, region = view3d()
    xdotool("mousemove", str(region.x + region.width // 2), str(window.height - (region.y + region.height // 2)))


def shot(name):
    os.makedirs(RAW, exist_ok=True)
    path = os.path.join(RAW, f"{name}.png")
    window, area, _ = view3d()
    with bpy.context.temp_override(window=window, area=area):
        bpy.ops.screen.screenshot(filepath=path)
    return path


def pixels(path, box, scale=1.0):
    """RGBA rows (top first) of screenshot `path` inside box (left, top, right, bottom), scaled."""
    image = bpy.data.images.load(path)
    try:
        w, h = image.size
        px = np.empty(w * h * 4, np.float32)
        image.pixels.foreach_get(px)
        left, top, right, bottom = box
        crop = px.reshape(h, w, 4)[::-1][top:bottom, left:right]  # Blender's rows run upwards
    finally:
        bpy.data.images.remove(image)
    if scale != 1.0:
        crop = resized(crop, scale)
    return crop


def resized(rgba, scale):
    """Box-filtered downscale (an image shrinks by area, not by picking pixels)."""
    image = bpy.data.images.new("fracterra crop", rgba.shape[1], rgba.shape[0], alpha=True)
    try:
        image.pixels.foreach_set(rgba[::-1].ravel())
        image.scale(int(rgba.shape[1] * scale), int(rgba.shape[0] * scale))
        w, h = image.size
        px = np.empty(w * h * 4, np.float32)
        image.pixels.foreach_get(px)
    finally:
        bpy.data.images.remove(image)
    return px.reshape(h, w, 4)[::-1]


def save_png(rgba, name):
    """Writes RGBA rows (top first) as docs' picture `name`."""
    h, w = rgba.shape[:2]
    image = bpy.data.images.new(name, w, h, alpha=False)
    try:
        image.pixels.foreach_set(rgba[::-1].ravel())
        image.filepath_raw = os.path.join(ARGS.out, name)
        image.file_format = "PNG"
        image.save()
    finally:
        bpy.data.images.remove(image)
    log("wrote", os.path.join(ARGS.out, name), f"{w} x {h}")


def pair(left, right, name, box, scale=1.0):
    a, b = pixels(left, box, scale), pixels(right, box, scale)
    gap = np.full((a.shape[0], 6, 4), (0.157, 0.157, 0.157, 1.0), np.float32)  # Blender's dark grey
    save_png(np.concatenate([a, gap, b], axis=1), name)


def heights(obj):
    co = np.empty(3 * len(obj.data.vertices), np.float32)
    obj.data.vertices.foreach_get("co", co)
    return co[2::3]


def fine_energy(z):
    """Per vertex of a square grid: (z less its 5 x 5 mean)^2, the energy of its finest texture."""
    side = int(round(math.sqrt(len(z))))
    grid = z.reshape(side, side).astype(np.float64)
    padded = np.pad(grid, 2, mode="edge")
    mean = sum(padded[i:i + side, j:j + side] for i in range(5) for j in range(5)) / 25.0
    return ((grid - mean) ** 2).ravel()


def state(name, what):
    """Prints what the sidebar shows (the settings) and what the mesh is."""
    obj = bpy.data.objects.get(name)
    if obj is None:
        log(f"{what}: no object {name}; objects {[o.name for o in bpy.data.objects]}")
        return None
    s, z = obj.fracterra_terrain, heights(obj)
    side = int(round(math.sqrt(len(z))))
    log(f"{what}: {name} {side}^2, highest {z.max():.4f}, mean {z.mean():.4f}; Detail Levels {s.levels}, "
        f"Erosion {s.erode_preset}, Mask {s.erosion_mask_source}, Auto Update {s.auto_update}, "
        f"error '{s.last_error}'; objects {[o.name for o in bpy.data.objects]}")
    return z


def set_view(distance, elevation, azimuth, target):
    _, area, _ = view3d()
    space = area.spaces[0]
    r3d = space.region_3d
    r3d.view_perspective = "PERSP"
    r3d.view_rotation = Euler((math.radians(elevation), 0.0, math.radians(azimuth))).to_quaternion()
    r3d.view_location = Vector(target)
    r3d.view_distance = distance
    space.shading.type = "SOLID"
    space.shading.show_cavity = True
    space.overlay.show_text = False
    space.show_region_hud = False  # the redo panel's header would stand in a corner of the crop


def wait(limit=900.0):
    yield from gui_harness.wait_for_jobs(limit=limit, then=STEP)


def edit(name, message, **settings):
    """A sidebar edit: the settings change, then the undo step the UI pushes."""
    s = bpy.data.objects[name].fracterra_terrain
    for k, v in settings.items():
        setattr(s, k, v)
    bpy.ops.ed.undo_push(message=message)


def regenerate():
    """The sidebar's Regenerate / Build Final button."""
    with in_view3d():
        result = bpy.ops.object.fracterra_terrain_regenerate("INVOKE_DEFAULT", True)
    gui_harness.check(result == {"RUNNING_MODAL"}, f"Regenerate: {result}")


def add_terrain(**settings):
    """Add > Mesh > Fractal Terrain as the menu runs it; the new object's name."""
    with in_view3d():
        result = bpy.ops.mesh.fracterra_terrain_add("INVOKE_DEFAULT", True, **settings)
    gui_harness.check(result == {"RUNNING_MODAL"}, f"Add: {result}")
    yield from wait()
    return bpy.context.active_object.name


def fracterra_tab():
    """Clicks the sidebar's Fracterra tab (the lowest of its tabs)."""
    window, area, _ = view3d()
    sidebar = next(r for r in area.regions if r.type == "UI")
    xdotool("mousemove", str(sidebar.x + sidebar.width - 10), str(window.height - (sidebar.y + sidebar.height) + 165),
            "click", "1")


def scroll_sidebar(clicks):
    window, area, _ = view3d()
    sidebar = next(r for r in area.regions if r.type == "UI")
    xdotool("mousemove", str(sidebar.x + sidebar.width // 2), str(window.height - (sidebar.y + sidebar.height // 2)))
    for _ in range(clicks):
        xdotool("click", "5")


def clear():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.context.scene.cursor.location = (0.0, 0.0, 0.0)  # where Add puts a terrain
    bpy.ops.ed.undo_push(message="the scene emptied")  # as a user's Delete pushes it


def mountain():
    set_view(**MOUNTAIN_VIEW)
    yield STEP
    name = yield from add_terrain()
    z0 = state(name, "the default Add")
    fracterra_tab()
    yield 1.0
    before = shot("default")
    edit(name, "Erosion", erode_preset="LAND")
    regenerate()
    yield from wait()
    z = state(name, "Rugged Mountains, Regenerate")
    log(f"highest point / the input's {z.max() / z0.max():.3f}, mean / the input's {z.mean() / z0.mean():.3f}")
    pair(before, shot("rugged"), "erosion-blender-before-after.png", MOUNTAIN_CROP, MOUNTAIN_SCALE)
    edit(name, "Auto Update", auto_update=True)
    edit(name, "Detail Levels", levels=10)  # Auto Update builds the Preview
    yield 1.0
    yield from wait()
    state(name, "Detail Levels 10, Auto Update")
    preview = shot("preview")
    regenerate()  # the button reads Build Final
    yield from wait()
    state(name, "Build Final")
    pair(preview, shot("final"), "erosion-blender-preview-final.png", MOUNTAIN_CROP, MOUNTAIN_SCALE)
    if ARGS.tryout:
        yield from tryout(name)
    edit(name, "Auto Update", auto_update=False)
    edit(name, "Detail Levels", levels=8)
    regenerate()
    yield from wait()
    obj = bpy.data.objects[name]
    co = np.empty(3 * len(obj.data.vertices), np.float32)
    obj.data.vertices.foreach_get("co", co)
    group = obj.vertex_groups.new(name="Erode")
    group.add([int(i) for i in np.flatnonzero(co[0::3] < 0.0)], 1.0, "REPLACE")
    bpy.ops.ed.undo_push(message="Vertex group")
    edit(name, "Mask", erosion_mask_source="VERTEX_GROUP", erosion_mask_group="Erode")
    bpy.context.window_manager.fracterra_erosion_advanced = True
    regenerate()
    yield from wait()
    z = state(name, "Mask: the left half")
    right = co[0::3] > 0.05
    if len(z) == len(z0):
        d = z[right] - z0[right]
        e, e0 = fine_energy(z), fine_energy(z0)
        side = int(round(math.sqrt(len(z))))
        risen = np.pad((z - z0 > 1e-3).reshape(side, side), 2)
        near = np.zeros((side, side), bool)  # within 2 samples of a rise, the 5 x 5 mean's reach
        for i in range(5):
            for j in range(5):
                near |= risen[i:i + side, j:j + side]
        away = right & ~near.ravel()
        log(f"right half: lowered by at most {max(0.0, -d.min()):.4f}, {np.mean(d > 1e-3):.1%} of it raised by "
            f"over 1 mm (median {np.median(d[d > 1e-3]):.4f}, at most {d.max():.3f}); its fine texture's energy "
            f"kept {e[right].sum() / e0[right].sum():.3f}, {e[away].sum() / e0[away].sum():.3f} on the "
            f"{away.sum() / right.sum():.0%} of it over 2 samples from a rise")
    scroll_sidebar(12)  # down to the Erosion box
    yield 1.0
    save_png(pixels(shot("mask"), MASK_CROP), "erosion-blender-mask.png")
    if ARGS.tryout:
        bpy.context.scene.cursor.location = (12.0, 0.0, 0.0)
        second = yield from add_terrain()
        state(second, "a second Add")
        state(name, "the first terrain after it")


def tryout(name):
    """Ctrl+Z and Ctrl+Shift+Z as keys after Build Final, then Esc during a levels-12 Regenerate."""
    pointer_to_view()
    yield STEP
    for key, what in (("ctrl+z", "Ctrl+Z"), ("ctrl+z", "Ctrl+Z again"), ("ctrl+shift+z", "Ctrl+Shift+Z"),
                      ("ctrl+shift+z", "Ctrl+Shift+Z again")):
        xdotool("key", key)
        yield 2.0
        yield from wait()
        state(name, what)
    before = heights(bpy.data.objects[name]).copy()
    edit(name, "Auto Update", auto_update=False)
    edit(name, "Detail Levels", levels=12)
    regenerate()
    started = time.time()
    yield 6.0
    shot("levels12-progress")
    pointer_to_view()
    yield 0.2
    pressed = time.time()
    xdotool("key", "Escape")
    yield from wait()
    log(f"Esc pressed {pressed - started:.1f} s into the build took effect {time.time() - pressed - STEP:.1f} s later")
    z = state(name, "after Esc")
    log("the mesh as before:", bool(len(z) == len(before) and np.array_equal(z, before)))


def sea():
    set_view(**SEA_VIEW)
    yield STEP
    name = yield from add_terrain(method="FBM", width=513, height=513, seed=7, falloff="NONE", sea="FRACTION",
                                  sea_fraction=0.3)
    z0 = state(name, "the fBm island")
    set_view(**SEA_VIEW)
    yield STEP
    before = shot("island")
    edit(name, "Erosion", erode_preset="LAND")
    regenerate()
    yield from wait()
    z = state(name, "the island, Rugged Mountains")
    sea_level = np.sort(z0)[int(0.3 * len(z0))]
    water = z0 <= sea_level
    log(f"sea level {sea_level:.4f}: {water.sum()} samples, moved by at most {np.abs(z - z0)[water].max():.6f}; "
        f"land below it after: {(z[~water] < sea_level).sum()}")
    pair(before, shot("island-rugged"), "erosion-sea-blender.png", SEA_CROP)


def scenario():
    _, area, _ = view3d()
    area.spaces[0].show_region_ui = True
    pointer_to_view()
    xdotool("key", "Escape")  # the splash screen
    yield STEP
    clear()
    yield STEP
    yield from mountain()
    clear()
    yield STEP
    yield from sea()


addon_harness.PACKAGE = addon_harness.install_and_enable(ARGS.zip).__name__
gui_harness.run_in_event_loop(scenario(), "erosion pictures")
