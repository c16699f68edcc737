# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on in Blender's real GUI (under Xvfb), installed from its zip, driven
through the event loop the way a user drives it: every menu the add-on adds is
opened, every operator of those menus run with its redo panel (Adjust Last
Operation) drawn, every sidebar panel shown, and the window saved as a
screenshot after each step (artifacts a person can open: --out).

It also checks what needs a window (undo: test_undo.py): the coastline's redo changes its level,
sizes beyond Blender's limit are a report, and a polyline is re-edited in
place from its sidebar panel. Panel and menu drawing errors only print a
traceback, so ctest fails on any "Traceback" in the log (FAIL_REGULAR_EXPRESSION).

Run as: xvfb-run blender --factory-startup --window-geometry 0 0 1280 800 \\
        --python test_gui.py -- --zip fracterra.zip --out shots/
"""

import argparse
import math
import os
import subprocess
import sys

import bpy
import numpy as np
from mathutils import Euler

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402
import gui_harness  # noqa: E402
from gui_harness import check, in_view3d, vertex_hash, view3d  # noqa: E402

gui_harness.PREFIX = "GUI CHECK FAILED: "
DRAWN = {}  # what drew at least once: class or menu function name -> count
STEP = 0.4  # seconds between steps: Blender redraws in between


def options():
    argv = sys.argv[sys.argv.index("--") + 1:]
    parser = argparse.ArgumentParser()
    parser.add_argument("--zip", required=True)
    parser.add_argument("--out", required=True, help="folder for the screenshots")
    return parser.parse_args(argv)


def count_draws(cls):
    """Wraps cls.draw to count its calls in DRAWN[cls.__name__] (an explicit
    signature: Blender passes as many arguments as the function declares)."""
    original = cls.draw

    def draw(self, context):
        DRAWN[cls.__name__] = DRAWN.get(cls.__name__, 0) + 1
        return original(self, context)
    cls.draw = draw


def xdotool(*args):
    subprocess.run(["xdotool", *args], check=True)


def pointer_to(region):
    """Moves the X pointer over the middle of `region` (Blender's y runs upwards)."""
    window = bpy.context.window_manager.windows[0]
    x = region.x + region.width // 2
    y = window.height - (region.y + region.height // 2)
    xdotool("mousemove", str(x), str(y))


class Shots:
    def __init__(self, folder):
        self.folder = folder
        self.n = 0
        os.makedirs(folder, exist_ok=True)

    def __call__(self, name):
        self.n += 1
        path = os.path.join(self.folder, f"{self.n:02d}-{name}.png")
        window, area, _ = view3d()
        with bpy.context.temp_override(window=window, area=area):
            bpy.ops.screen.screenshot(filepath=path)
        check(os.path.getsize(path) > 1000, f"screenshot {path} is empty")


def instrument():
    """Counts the draws of every panel, menu entry and redo panel of the add-on."""
    blender = addon_harness.submodule("blender")
    for cls in blender.classes:
        if issubclass(cls, (bpy.types.Panel, bpy.types.Operator, bpy.types.AddonPreferences)) and "draw" in cls.__dict__:
            count_draws(cls)
    for menu, draw in blender.MENUS:
        menu.remove(draw)

        def counted(self, context, draw=draw):
            DRAWN[draw.__name__] = DRAWN.get(draw.__name__, 0) + 1
            draw(self, context)
        menu.append(counted)


def open_menu(menu, shot, ups=0):
    """Opens `menu` over the 3D view as Shift+A would, moves `ups` entries up
    from the first (menus wrap round: 1 is the last entry, where the add-on
    appends its own) and saves a screenshot of it."""
    pointer_to(view3d()[2])
    yield STEP  # Blender sees the pointer move before the menu opens under it
    with in_view3d():
        bpy.ops.wm.call_menu(name=menu)
    yield 0.1  # before a tooltip opens (it would take the first key)
    for _ in range(ups):
        xdotool("key", "Up")
    yield 0.1  # drawn, but still before the tooltip of the highlighted entry (0.5 s)
    shot(f"menu-{menu}")


def choose_from_menu(menu, ups, shot):
    """Picks the add-on's entry of `menu` with the keys, as a user can."""
    yield from open_menu(menu, shot, ups)
    xdotool("key", "Return")
    yield 2 * STEP


def wait_for_jobs(limit=60.0):
    return gui_harness.wait_for_jobs(limit, STEP)


def expand_redo_panel():
    """Clicks the collapsed Adjust Last Operation panel open, as a user does. Its
    header is a toggle and Blender keeps it open or closed from one operator to
    the next, so it clicks only while the panel is a bare header (and looks again)."""
    for _attempt in range(3):
        _, area, _ = view3d()
        hud = next((r for r in area.regions if r.type == "HUD" and r.width > 1), None)
        check(hud is not None, "no redo panel (Adjust Last Operation) appeared")
        if hud is None or hud.height > 60:  # open: more than its header
            break
        window = bpy.context.window_manager.windows[0]
        xdotool("mousemove", str(hud.x + 20), str(window.height - (hud.y + hud.height - 10)), "click", "1")
        yield STEP
    yield STEP


def sidebar_tab(panel):
    """Clicks down the sidebar's strip of tabs until `panel` (a class name) has
    drawn: the Fracterra tab is shown."""
    window = bpy.context.window_manager.windows[0]
    sidebar = next(r for r in view3d()[1].regions if r.type == "UI")
    x = sidebar.x + sidebar.width - 8
    top = window.height - (sidebar.y + sidebar.height)
    # From under the header the sidebar overlaps (a click there opens its shading popover).
    for y in range(top + 70, top + sidebar.height, 25):
        if DRAWN.get(panel, 0):
            return
        xdotool("mousemove", str(x), str(y), "click", "1")
        yield STEP


def run_from_script(idname):
    """Runs an operator as its menu entry does (invoke, registered for the redo
    panel, its own undo step). Picking these entries with the keys worked only
    for the first menu under Xvfb (Return was ignored later), so the menus are
    opened and shot above, and the operators run from here."""
    category, name = idname.split(".")
    with in_view3d():
        result = getattr(getattr(bpy.ops, category), name)("INVOKE_DEFAULT", True)
    check(result & {"FINISHED", "RUNNING_MODAL"}, f"{idname}: {result}")
    yield STEP


def planet_steps(shot):
    """Add > Mesh > Fractal Planet as a new user would: its redo panel, the
    sidebar, a new seed and sea fraction, a higher level cancelled with Esc
    (the sidebar then shows the level that is there)."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.context.scene.cursor.location = (0.0, 0.0, 0.0)
    # The menu (Fractal Planet under Fractal Terrain) is shot; the
    # entry is then run as the menu runs it (Return in a second menu is
    # ignored under Xvfb, see run_from_script).
    yield from open_menu("VIEW3D_MT_mesh_add", shot)
    xdotool("key", "Escape")
    yield STEP
    # Level 5, not the default 8: Xvfb's software OpenGL redraws a 393 218-vertex
    # planet in seconds, at every step (the defaults took 88 s here, level 5 a
    # fraction); docs/planets.md shows the defaults' screenshots.
    with in_view3d():
        result = bpy.ops.mesh.fracterra_planet_add("INVOKE_DEFAULT", True, level=5)
    check(result & {"FINISHED", "RUNNING_MODAL"}, f"Add Fractal Planet: {result}")
    yield from wait_for_jobs()
    planet = bpy.context.active_object
    check(planet is not None and planet.fracterra_planet.is_planet, "Add > Mesh > Fractal Planet added no planet")
    settings = planet.fracterra_planet
    check(len(planet.data.vertices) == 6 * 4 ** settings.level + 2, "the planet is built at its Final level")
    with in_view3d():
        bpy.ops.view3d.view_selected()
        bpy.ops.view3d.zoom(delta=-1)
    yield from expand_redo_panel()
    shot("planet-add-redo-panel")
    check(DRAWN.get("FRACTERRA_OT_planet_add", 0) > 0, "the planet's redo panel was not drawn")
    yield from sidebar_tab("FRACTERRA_PT_planet")
    check(DRAWN.get("FRACTERRA_PT_planet", 0) > 0, "the Fractal Planet sidebar panel was not drawn")
    shot("planet-sidebar")
    before = vertex_hash(planet)
    settings.seed, settings.sea_fraction = 12, 0.5
    with in_view3d():
        bpy.ops.object.fracterra_planet_regenerate("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    check(vertex_hash(planet) != before, "Regenerate with seed 12 did not change the planet")
    shot("planet-seed-12-sea-half")
    before, level = vertex_hash(planet), settings.level
    settings.level = 10  # 6.3 M vertices: long enough to cancel
    with in_view3d():
        bpy.ops.object.fracterra_planet_regenerate("INVOKE_DEFAULT", True)
    yield 0.5
    check(addon_harness.submodule("blender.common.jobs").busy(), "the level 10 planet finished before Esc")
    shot("planet-progress")
    pointer_to(view3d()[2])
    xdotool("key", "Escape")
    yield from wait_for_jobs()
    check(vertex_hash(planet) == before and settings.level == level,
          f"after Esc the planet is the same and the sidebar shows its level {level}, not {settings.level}")
    shot("planet-after-esc")


def same_view():
    """The walk-through's one view: the 10 m terrain from the south-east, a little above."""
    r3d = view3d()[1].spaces[0].region_3d
    r3d.view_perspective = "PERSP"
    r3d.view_location = (0.0, 0.0, 0.6)
    r3d.view_rotation = Euler((math.radians(62), 0.0, math.radians(35))).to_quaternion()
    r3d.view_distance = 17.0


def grid_heights(obj):
    """(z (ny, nx), x (nx,), y (ny,)) of a terrain's vertex grid."""
    co = np.empty(3 * len(obj.data.vertices), dtype=np.float32)
    obj.data.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3).astype(np.float64)
    nx = int(np.sum(co[:, 1] == co[0, 1]))
    return co[:, 2].reshape(-1, nx), co[:nx, 0], co[::nx, 1]


def off_surface(terrain, points):
    """|z - the terrain's bilinear surface| at each (x, y, z) of `points` (local frame)."""
    z, x, y = grid_heights(terrain)
    c = np.interp(points[:, 0], x, np.arange(len(x)))
    r = np.interp(points[:, 1], y, np.arange(len(y)))
    c0, r0 = np.minimum(c.astype(int), len(x) - 2), np.minimum(r.astype(int), len(y) - 2)
    fc, fr = c - c0, r - r0
    top = z[r0, c0] * (1 - fc) + z[r0, c0 + 1] * fc
    bottom = z[r0 + 1, c0] * (1 - fc) + z[r0 + 1, c0 + 1] * fc
    return np.abs(points[:, 2] - (top * (1 - fr) + bottom * fr))


def curve_points(obj):
    parts = []
    for spline in obj.data.splines:
        co = np.empty(4 * len(spline.points), dtype=np.float32)
        spline.points.foreach_get("co", co)
        parts.append(co.reshape(-1, 4)[:, :3].astype(np.float64))
    return np.concatenate(parts)


def sidebar_shows(panel):
    """True when `panel` (a class name) polls true in the sidebar's own context."""
    cls = getattr(bpy.types, panel)
    with in_view3d("UI"):
        return cls.poll(bpy.context)


def walkthrough(shot, pov_out):
    """What a new user does, from the default scene (its camera and light; no cube), in one
    view: add a terrain, erode it, trace its rivers, a coastline, re-edit it
    (a new seed, a Strength drag with Auto Update) over a kept Final, undo,
    Esc, hide it, a planet, a lightning bolt and a Koch curve, then export to
    POV-Ray and render. The screenshots are docs/blender.md's walk-through."""
    objects = addon_harness.submodule("blender.build.objects")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    # The default scene's camera and point light, where Blender's start-up file has them.
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    camera.location, camera.rotation_euler = (7.3589, -6.9258, 4.9583), (1.1093, 0.0, 0.8149)
    light = bpy.data.objects.new("Light", bpy.data.lights.new("Light", "POINT"))
    light.location, light.data.energy = (4.0762, 1.0055, 5.9039), 1000.0
    for obj in (camera, light):
        bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = camera
    bpy.context.scene.cursor.location = (0.0, 0.0, 0.0)
    yield from run_from_script("mesh.fracterra_terrain_add")  # its menu was picked and shot above
    yield from wait_for_jobs()
    terrain = bpy.context.active_object
    check(objects.is_terrain(terrain), "Add > Mesh > Fractal Terrain added no terrain")
    name = terrain.name
    settings = terrain.fracterra_terrain
    yield from sidebar_tab("FRACTERRA_PT_terrain")
    same_view()
    yield STEP
    shot("walk-terrain-added")
    # Erode (Rugged Mountains) and Rivers and Lakes, from the sidebar.
    settings.erode_preset = "LAND"
    with in_view3d():
        bpy.ops.object.fracterra_terrain_regenerate("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    check("fracterra_flow" in terrain.data.attributes, "Rugged Mountains did not erode the terrain")
    with in_view3d():
        bpy.ops.object.fracterra_rivers("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    check(any(c.get("fracterra_kind") == "RIVERS" for c in terrain.children), "no rivers traced")
    with in_view3d():
        bpy.ops.curve.fracterra_coastline_add("INVOKE_DEFAULT", True, use_quantile=True, quantile=0.3)
    yield from wait_for_jobs()
    coast = bpy.context.active_object
    bpy.context.view_layer.objects.active = terrain
    yield STEP
    shot("walk-eroded-rivers-coastline")
    # A Final of 513 x 513 (Build Final), then Auto Update edits: seed 21 and a Strength drag.
    settings.levels = 9
    with in_view3d():
        bpy.ops.object.fracterra_terrain_regenerate("INVOKE_DEFAULT", True)
    yield from wait_for_jobs(120.0)
    final = terrain.data
    check(objects.mesh_level(terrain) == ("Final", 513, 513), f"Build Final: {objects.mesh_level(terrain)}")
    shot("walk-final-513")
    bpy.ops.ed.undo_push(message="before the re-edit")
    seed, coast_name = settings.seed, coast.name
    settings.auto_update = True
    settings.seed = seed + 20
    yield STEP
    for strength in (0.6, 0.7, 0.8):  # what a drag sets, one value per redraw
        settings.strength = strength
        yield 0.2
    bpy.ops.ed.undo_push(message="Strength")
    check(terrain.fracterra_final == final, "an Auto Update edit threw the Final away")
    check(objects.mesh_level(terrain)[0] == "Preview" and objects.out_of_date(terrain) == [],
          f"after the edit: {objects.mesh_level(terrain)}, out of date {objects.out_of_date(terrain)}")
    error = off_surface(terrain, curve_points(coast))
    check(error.max() < 1e-3, f"the coastline is {error.max():.3f} m off the re-edited surface")
    yield STEP
    shot("walk-auto-update-final-kept")
    # Ctrl+Z: back to before the re-edit (the Final and its seed).
    with in_view3d():
        bpy.ops.ed.undo()
    yield STEP
    terrain = bpy.data.objects[name]
    settings, coast = terrain.fracterra_terrain, bpy.data.objects[coast_name]
    check(objects.mesh_level(terrain) == ("Final", 513, 513) and settings.seed == seed
          and not objects.out_of_date(terrain),
          f"after undo: {objects.mesh_level(terrain)}, seed {settings.seed}, out of date {objects.out_of_date(terrain)}")
    shot("walk-after-undo")
    # Esc: a 2049^2 Final started and cancelled; mesh and sidebar stay as they were.
    settings.auto_update = False
    settings.levels = 11
    with in_view3d():
        bpy.ops.object.fracterra_terrain_regenerate("INVOKE_DEFAULT", True)
    yield 0.5
    shot("walk-build-final-progress")
    pointer_to(view3d()[2])
    xdotool("key", "Escape")
    yield from wait_for_jobs()
    check(settings.levels == 9 and len(terrain.data.vertices) == 513 * 513 and not objects.out_of_date(terrain),
          f"after Esc: levels {settings.levels}, {len(terrain.data.vertices)} vertices")
    shot("walk-after-esc")
    # Hide the terrain (H over the view): its water and coastline go with it; the sidebar still edits it.
    bpy.ops.object.select_all(action="DESELECT")
    terrain.select_set(True)
    bpy.context.view_layer.objects.active = terrain
    pointer_to(view3d()[2])
    yield STEP
    xdotool("key", "h")
    yield 2 * STEP
    shown = [c.name for c in terrain.children if c.visible_get()]
    check(not terrain.visible_get() and not shown, f"hidden terrain, children still shown: {shown}")
    check(sidebar_shows("FRACTERRA_PT_terrain"), "the sidebar lost the hidden active terrain")
    shot("walk-terrain-hidden")
    xdotool("key", "alt+h")
    yield 2 * STEP
    check(terrain.visible_get() and coast.visible_get(), "Alt+H did not show the terrain and its coastline again")
    # A lightning bolt striking the mountain, then a Koch curve beside it.
    bpy.context.scene.cursor.location = (1.0, 0.5, 0.0)
    with in_view3d():
        bpy.ops.curve.fracterra_polyline_add("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    bolt = bpy.context.active_object
    check(bolt.parent == terrain, "the bolt that struck the terrain is not its child")
    bpy.context.scene.cursor.location = (0.0, -7.5, 0.0)
    with in_view3d():
        bpy.ops.curve.fracterra_polyline_add("INVOKE_DEFAULT", True, method="KOCH", depth=4)
    yield from wait_for_jobs()
    koch = bpy.context.active_object
    p = curve_points(koch)
    check(np.ptp(p[:, 2]) == 0.0 and np.ptp(p[:, 1]) > 1.0, "the Koch curve is not flat on the ground")
    bpy.context.view_layer.objects.active = terrain
    yield STEP
    shot("walk-bolt-and-koch")
    # Export to POV-Ray through the default camera and light, and render.
    path = os.path.join(pov_out, "walkthrough.pov")
    with in_view3d():
        result = bpy.ops.export_scene.fracterra_pov(filepath=path, render=True, width=640, height=360)
    check(result == {"FINISHED"} and os.path.getsize(path.replace(".pov", ".png")) > 1000,
          f"the POV-Ray export and render: {result}")
    # A planet, in a view of its own.
    for obj in (terrain, coast, bolt, koch):
        obj.hide_set(True)
    bpy.context.scene.cursor.location = (0.0, 0.0, 0.0)
    with in_view3d():  # level 6: Xvfb's software OpenGL redraws the default level 8 in seconds
        bpy.ops.mesh.fracterra_planet_add("INVOKE_DEFAULT", True, level=6)
    yield from wait_for_jobs(120.0)
    planet = bpy.context.active_object
    check(objects.is_planet(planet), "no planet added")
    with in_view3d():
        bpy.ops.view3d.view_selected()
    yield from sidebar_tab("FRACTERRA_PT_planet")
    yield STEP
    shot("walk-planet")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)


def scenario(shot):
    window, area, region = view3d()
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    area.spaces[0].show_region_ui = True
    pointer_to(region)
    xdotool("key", "Escape")  # the splash screen
    yield 1.0  # the sidebar laid out before its tabs are clicked

    # Every menu the add-on adds, opened as a user opens it.
    for menu, entry in (("VIEW3D_MT_mesh_add", "menu_mesh_add"), ("VIEW3D_MT_curve_add", "menu_curve_add"),
                        ("VIEW3D_MT_object", "menu_object"), ("TOPBAR_MT_file_export", "menu_file_export")):
        yield from open_menu(menu, shot)
        check(DRAWN.get(entry, 0) > 0, f"the add-on's entry in {menu} was not drawn")
        xdotool("key", "Escape")
        yield STEP

    # Add > Mesh > Fractal Terrain with its redo panel; the sidebar's Fracterra tab.
    # (The add-on appends Fractal Terrain, then Fractal Planet: 2 up from the top.)
    yield from choose_from_menu("VIEW3D_MT_mesh_add", 2, shot)
    yield from wait_for_jobs()
    check(bpy.context.active_object is not None and bpy.context.active_object.fracterra_terrain.is_terrain,
          "Add > Mesh > Fractal Terrain added no terrain")
    yield from expand_redo_panel()
    shot("terrain-add-redo-panel")
    check(DRAWN.get("FRACTERRA_OT_terrain_add", 0) > 0, "the terrain's redo panel was not drawn")
    yield from sidebar_tab("FRACTERRA_PT_terrain")
    check(DRAWN.get("FRACTERRA_PT_terrain", 0) > 0, "the Fractal Terrain sidebar panel was not drawn")
    shot("terrain-sidebar")

    # Falloff 'Custom' from the sidebar: an object's outline (a circle drawn over the
    # terrain), then an image; its fields drawn, Regenerate applies it.
    terrain = bpy.context.active_object
    with in_view3d():
        bpy.ops.curve.primitive_bezier_circle_add(radius=3.0, location=(1.0, 0.0, 0.0))
    circle = bpy.context.active_object
    bpy.context.view_layer.objects.active = terrain
    settings = terrain.fracterra_terrain
    settings.falloff, settings.falloff_mask_source, settings.falloff_mask_object = "CUSTOM", "OBJECT", circle.name
    settings.falloff_width = 0.2
    with in_view3d():
        bpy.ops.object.fracterra_terrain_regenerate("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    corner = terrain.data.vertices[0].co.z
    check(abs(corner - settings.edge_level) < 1e-6, f"the custom falloff left the corner at {corner}")
    shot("terrain-sidebar-custom-falloff-object")
    mask = bpy.data.images.new("Mask", 64, 64)
    settings.falloff_mask_source, settings.falloff_mask_image_pick = "IMAGE", "Mask"
    yield STEP
    shot("terrain-sidebar-custom-falloff-image")
    check(settings.falloff_mask_image == "Mask", "the mask image picker did not store the image")
    settings.falloff = "RADIAL"
    bpy.data.images.remove(mask)
    bpy.data.objects.remove(circle)
    with in_view3d():
        bpy.ops.object.fracterra_terrain_regenerate("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    settings.erode_preset = "LAND"
    yield STEP
    shot("terrain-sidebar-erosion")  # the Erosion box's heading, not cut to "Erosi..."
    settings.erode_preset = "NONE"
    yield STEP

    # (Undo after Regenerate: test_undo.py, which checks the settings shown too.)
    terrain = bpy.context.active_object
    name = terrain.name

    # Measures, then the coastline and its redo.
    with in_view3d():
        check(bpy.ops.object.fracterra_measure("INVOKE_DEFAULT", True) == {"FINISHED"}, "Measure failed")
    yield STEP
    check(terrain.fracterra_measures.kind == "terrain", "Measure stored nothing")
    check(DRAWN.get("FRACTERRA_PT_measures", 0) > 0, "the measures panel was not drawn")
    yield from run_from_script("curve.fracterra_coastline_add")
    yield from wait_for_jobs()
    yield from expand_redo_panel()
    shot("coastline-redo-panel")
    op = bpy.context.window_manager.operators[-1]
    check(op.bl_idname == "CURVE_OT_fracterra_coastline_add", f"last operator is {op.bl_idname}")
    stats = [v.co.z for v in bpy.data.objects[name].data.vertices]
    level = min(stats) + 0.8 * (max(stats) - min(stats))
    op.properties.use_quantile = False
    op.properties.level = level
    with in_view3d():
        check(bpy.ops.ed.undo_redo() == {"FINISHED"}, "the coastline's redo did not run")
    yield STEP
    coast = bpy.context.active_object
    zs = [p.co.z for s in coast.data.splines for p in s.points]
    check(coast.name.endswith("Coastline") and zs and all(abs(z - level) < 1e-3 for z in zs),
          f"the coastline's redo did not move it to level {level:.3f}")
    shot("coastline-after-redo")

    # Beyond Blender's limit (levels 13 is not offered; 8193 x 8193 samples): a report,
    # nothing added, no traceback.
    count = len(bpy.data.objects)
    try:
        with in_view3d():
            bpy.ops.mesh.fracterra_terrain_add("INVOKE_DEFAULT", method="FBM", width=8193, height=8193)
        check(False, "an 8193 x 8193 terrain was not refused")
    except RuntimeError as e:  # a script sees the error report as RuntimeError; the user sees the report
        check(str(e).startswith("Error: Refused before generating"), f"8193 x 8193: {e}")
    yield STEP
    check(len(bpy.data.objects) == count, "a refused terrain left an object")
    shot("too-large-report")

    # A long job shows its progress in the status bar, and Esc cancels it: nothing is added.
    count = len(bpy.data.objects)
    meshes = len(bpy.data.meshes)
    progress = addon_harness.submodule("blender.common.jobs")
    with in_view3d():
        result = bpy.ops.mesh.fracterra_terrain_add("INVOKE_DEFAULT", True, levels=12)
    check(result == {"RUNNING_MODAL"}, f"Add Terrain from the menu did not run in the background: {result}")
    yield 0.5
    check(progress.busy(), "the levels 12 terrain finished before it could be cancelled")
    shot("progress-in-status-bar")
    pointer_to(view3d()[2])
    xdotool("key", "Escape")
    yield from wait_for_jobs()
    check(len(bpy.data.objects) == count and len(bpy.data.meshes) == meshes,
          "a cancelled terrain left an object or a mesh")
    shot("after-cancel")

    # Add > Curve > Fractal Polyline at the 3D cursor, re-edited in place from its panel.
    bpy.context.scene.cursor.location = (3.0, 0.0, 0.0)
    yield from run_from_script("curve.fracterra_polyline_add")
    yield from wait_for_jobs()
    check(bpy.context.active_object.fracterra_polyline.is_polyline, "Add > Curve > Fractal Polyline added nothing")
    yield from expand_redo_panel()
    shot("polyline-redo-panel")
    check(DRAWN.get("FRACTERRA_OT_polyline_add", 0) > 0, "the polyline's redo panel was not drawn")
    bolt = bpy.context.active_object
    bolt_name, points = bolt.name, len(bolt.data.splines[0].points)
    bolt.fracterra_polyline.depth = 5
    with in_view3d():
        bpy.ops.object.fracterra_polyline_regenerate("INVOKE_DEFAULT", True)
    yield from wait_for_jobs()
    check(bpy.context.active_object.name == bolt_name, "the polyline was not regenerated in place")
    check(len(bpy.data.objects[bolt_name].data.splines[0].points) == 2 ** 5 + 1 != points,
          "the polyline's new depth did not apply")
    yield from sidebar_tab("FRACTERRA_PT_polyline")
    check(DRAWN.get("FRACTERRA_PT_polyline", 0) > 0, "the Fractal Polyline sidebar panel was not drawn")
    shot("polyline-sidebar")

    # Object > Fractalize on a cube, and File > Export > POV-Ray (its file browser, closed).
    with in_view3d():
        bpy.ops.mesh.primitive_cube_add(location=(-7, 0, 1))  # beside the 10 m terrain, in view
    yield STEP
    faces = len(bpy.context.active_object.data.polygons)
    yield from run_from_script("object.fracterra_fractalize")
    yield from wait_for_jobs()
    check(len(bpy.context.active_object.data.polygons) > faces, "Object > Fractalize did not refine the cube")
    yield from expand_redo_panel()
    shot("fractalize-redo-panel")
    yield from run_from_script("export_scene.fracterra_pov")
    yield 1.0
    shot("export-pov-file-browser")
    xdotool("key", "Escape")
    yield STEP
    yield from planet_steps(shot)
    yield from walkthrough(shot, shot.folder)
    with in_view3d():
        bpy.ops.preferences.addon_show(module=addon_harness.PACKAGE)  # the preferences window
    yield 1.0
    shot("preferences")
    check(DRAWN.get("FracterraPreferences", 0) > 0, "the add-on's preferences were not drawn")


def main():
    args = options()
    addon_harness.PACKAGE = addon_harness.install_and_enable(args.zip).__name__
    instrument()
    gui_harness.run_in_event_loop(scenario(Shots(args.out)), "GUI test",
                                  at_end=lambda: print(f"GUI test drew: {sorted(DRAWN)}", flush=True))


main()
