"""Rivers and Lakes of a terrain in real Blender: the operator traces them
through the library's pipeline, so they are the rivers `fracterra terrain
--rivers` writes for the same settings (the CLI, another front end), a tiling
terrain's included; rivers are curves whose bevel follows the width, lakes
and the sea flat meshes at their levels, all with the water material and
parented to the terrain; Regenerate retraces them without duplicating
anything; the coastline and the water objects edit their terrain from the
sidebar; the default lightning bolt over a terrain strikes its surface."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402
from test_erosion import _cli, _flag  # noqa: E402

import bpy  # noqa: E402
import numpy as np  # noqa: E402
from mathutils import Vector  # noqa: E402

clear_scene = addon_harness.clear_scene


def core():
    return addon_harness.submodule("core")


def kinds(terrain):
    return {c.get("fracterra_kind"): c for c in terrain.children}


def cli_rivers(settings):
    """The rivers `fracterra terrain ... --rivers r.json` traces for the object's settings."""
    params = core().params
    values = params.values_of(settings)
    args = [_cli(), "terrain"]
    for p in params.library_params("terrain"):
        if p.name not in ("width", "height", "center_x", "center_y"):
            args += _flag(p, values[p.name])
    if settings.erode_preset not in ("NONE", "CUSTOM"):
        args += ["--erode", settings.erode_preset.lower()]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "r.json")
        subprocess.run(args + ["--rivers", out], check=True, capture_output=True)
        return json.loads(open(out).read())


def spline_points(curve):
    out = []
    for s in curve.splines:
        co = np.empty(4 * len(s.points), dtype=np.float32)
        s.points.foreach_get("co", co)
        r = np.empty(len(s.points), dtype=np.float32)
        s.points.foreach_get("radius", r)
        out.append((co.reshape(-1, 4)[:, :3], r))
    return out


class RiversTest(unittest.TestCase):
    def setUp(self):
        clear_scene()
        for curve in list(bpy.data.curves):  # clear_scene leaves curves
            bpy.data.curves.remove(curve)

    def add(self, **kw):
        args = dict(levels=6, seed=5, erode_preset="VALLEYS")
        args.update(kw)
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(**args), {"FINISHED"})
        return bpy.context.active_object

    def trace(self, terrain):
        bpy.context.view_layer.objects.active = terrain
        self.assertEqual(bpy.ops.object.fracterra_rivers(), {"FINISHED"})
        return kinds(terrain)

    def check_as_cli(self, terrain, rivers):
        """The curve's splines are the CLI's polylines, point for point, in the terrain's frame."""
        settings = terrain.fracterra_terrain
        try:
            want = cli_rivers(settings)["polylines"]
        except unittest.SkipTest:  # no CLI (Blender 4.3's root): the rest of the test still runs
            return
        got = spline_points(rivers.data)
        self.assertEqual(len(got), len([p for p in want if len(p["points"]) >= 2]))
        half = 0.5 * settings.world_size
        k = 1.0  # the network's world units are the terrain's local units (x spans World Size)
        for (co, r), line in zip(got, (p for p in want if len(p["points"]) >= 2)):
            pts = np.array(line["points"], dtype=np.float64)
            np.testing.assert_allclose(co[:, 0], pts[:, 0] * k - half, atol=1e-4)
            np.testing.assert_allclose(co[:, 1], pts[:, 1] * k - half, atol=1e-4)
            np.testing.assert_allclose(co[:, 2], pts[:, 2], atol=1e-4)
            np.testing.assert_allclose(r, np.array(line["radii"]) * k, rtol=1e-5)

    def assert_one_of_each(self, terrain):
        """One object of each water kind, and no water data left without an object."""
        made = [c.get("fracterra_kind") for c in terrain.children if c.get("fracterra_kind")]
        self.assertEqual(len(made), len(set(made)), made)
        self.assertEqual(len(bpy.data.objects), 1 + len(made))
        self.assertEqual(len(bpy.data.curves), sum(k in ("RIVERS", "RIVER_PROFILE") for k in made))
        self.assertEqual(len(bpy.data.meshes), 1 + sum(k in ("LAKES", "SEA") for k in made))

    def test_rivers_lakes_and_sea_are_objects_of_the_terrain(self):
        terrain = self.add(sea="FRACTION", sea_fraction=0.2)
        made = self.trace(terrain)
        self.assertTrue(terrain.fracterra_terrain.rivers, "stored with the terrain's settings")
        self.assertIn("RIVERS", made)
        self.assertIn("SEA", made)
        rivers = made["RIVERS"]
        self.assertEqual(rivers.type, "CURVE")
        self.assertIsNotNone(rivers.data.bevel_object, "the bevel follows each point's radius")
        radii = np.concatenate([r for _co, r in spline_points(rivers.data)])
        self.assertGreater(radii.max(), 2 * radii.min(), "widths follow the discharge")
        self.check_as_cli(terrain, rivers)
        sea = made["SEA"]
        z = np.array([v.co.z for v in sea.data.vertices])
        self.assertEqual(z.min(), z.max(), "flat")
        # At the sea's level: the highest sea cell. The sea is the terrain's own
        # (the landform flattened 20% of the samples), up to 1e-3 of the relief
        # above its floor (erosion lays sediment there): measured 24% below it.
        heights = np.array([v.co.z for v in terrain.data.vertices])
        below = np.mean(heights <= z[0])
        self.assertGreater(below, 0.18)
        self.assertLessEqual(below, 0.3)
        for kind in ("RIVERS", "SEA") + (("LAKES",) if "LAKES" in made else ()):
            obj = made[kind]
            self.assertIs(obj.parent, terrain)
            self.assertEqual(obj.data.materials[0].name, "Fracterra Water")

    def test_lakes_are_flat_at_their_levels(self):
        # No erosion: a fractal terrain is full of closed hollows.
        terrain = self.add(erode_preset="NONE")
        made = self.trace(terrain)
        self.assertIn("LAKES", made)
        z = np.array([v.co.z for v in made["LAKES"].data.vertices])
        self.assertGreater(len(z), 0)
        # Every lake vertex is at a level some lake has (levels from the library).
        settings = terrain.fracterra_terrain
        hf, _maps, water = core().build_terrain_rivers(core().params.values_of(settings), core().params.RIVERS_PARAMS)
        hf.close()
        self.assertTrue(np.all(np.min(np.abs(z[:, None] - water.levels[None, :]), axis=1) < 1e-5))

    def test_a_tiling_terrain_gives_the_clis_wrapping_rivers(self):
        terrain = self.add(method="MIDPOINT", periodic=True)
        rivers = self.trace(terrain)["RIVERS"]
        self.check_as_cli(terrain, rivers)

    def test_regenerate_retraces_without_duplicating(self):
        terrain = self.add(sea="FRACTION", sea_fraction=0.2)
        self.trace(terrain)
        rivers = kinds(terrain)["RIVERS"]
        rivers.data.materials[0] = bpy.data.materials.new("Mine")
        terrain.fracterra_terrain.seed = 8
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assert_one_of_each(terrain)
        self.assertIs(kinds(terrain)["RIVERS"], rivers, "the same object, its data replaced")
        self.assertEqual(rivers.data.materials[0].name, "Mine", "what the user set stays")
        self.check_as_cli(terrain, rivers)
        # Again through the operator, from the river itself: still one of each.
        bpy.context.view_layer.objects.active = rivers
        self.assertEqual(bpy.ops.object.fracterra_rivers(), {"FINISHED"})
        self.assert_one_of_each(terrain)
        # Remove: gone, and off.
        self.assertEqual(bpy.ops.object.fracterra_rivers(remove=True), {"FINISHED"})
        self.assertFalse(terrain.fracterra_terrain.rivers)
        self.assertEqual([c for c in terrain.children if c.get("fracterra_kind")], [])
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertEqual([c for c in terrain.children if c.get("fracterra_kind")], [])

    def test_water_and_coastline_edit_their_terrain_from_the_sidebar(self):
        terrain = self.add(sea="FRACTION", sea_fraction=0.2)
        self.trace(terrain)
        self.assertEqual(bpy.ops.curve.fracterra_coastline_add(), {"FINISHED"})
        coast = bpy.context.active_object
        self.assertEqual(coast.get("fracterra_kind"), "COASTLINE")
        terrain_of = addon_harness.submodule("blender.build.water").terrain_of
        for obj in [coast] + list(kinds(terrain).values()):
            self.assertIs(terrain_of(obj), terrain, obj.name)
            bpy.context.view_layer.objects.active = obj
            # The terrain panel and Regenerate work with it active.
            panel = bpy.types.FRACTERRA_PT_terrain
            self.assertTrue(panel.poll(bpy.context))
            self.assertTrue(bpy.ops.object.fracterra_terrain_regenerate.poll(), obj.name)
        # Regenerate from the coastline regenerates its terrain.
        bpy.context.view_layer.objects.active = coast
        before = np.array([v.co.z for v in terrain.data.vertices])
        terrain.fracterra_terrain.seed += 1
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertFalse(np.array_equal(before, [v.co.z for v in terrain.data.vertices]))

    def test_the_default_bolt_strikes_the_terrain_surface(self):
        terrain = self.add(erode_preset="NONE")
        terrain.location = (0.3, -0.2, 0.5)
        bpy.context.view_layer.update()
        bpy.context.scene.cursor.location = (1.0, 0.5, 0.0)
        self.assertEqual(bpy.ops.curve.fracterra_polyline_add(), {"FINISHED"})
        bolt = bpy.context.active_object
        end = bolt.matrix_world @ Vector(bolt.fracterra_polyline.end)
        # The surface under the cursor, from the mesh itself (bilinear over its grid).
        n = 2 ** 6 + 1
        z = np.array([v.co.z for v in terrain.data.vertices]).reshape(n, n)
        half = 0.5 * terrain.fracterra_terrain.world_size
        step = 2 * half / (n - 1)
        lx, ly = end.x - terrain.location.x, end.y - terrain.location.y
        fx, fy = (lx + half) / step, (ly + half) / step
        i, j = int(fx), int(fy)
        tx, ty = fx - i, fy - j
        surface = ((1 - tx) * (1 - ty) * z[j, i] + tx * (1 - ty) * z[j, i + 1] + (1 - tx) * ty * z[j + 1, i]
                   + tx * ty * z[j + 1, i + 1]) + terrain.location.z
        # A triangle of the quad against the bilinear patch: within the quad's own spread.
        spread = np.ptp(z[j:j + 2, i:i + 2])
        self.assertAlmostEqual(end.z, surface, delta=max(spread, 1e-4))
        self.assertGreater(end.z, 0.5, "not z = 0 inside the mountain")
        start = bolt.matrix_world @ Vector(bolt.fracterra_polyline.start)
        self.assertAlmostEqual(start.z - end.z, 10.0, places=4)
        # Off the terrain: the bolt as before, down to the cursor.
        bpy.context.scene.cursor.location = (50.0, 50.0, 0.0)
        self.assertEqual(bpy.ops.curve.fracterra_polyline_add(), {"FINISHED"})
        self.assertEqual(tuple(bpy.context.active_object.fracterra_polyline.end), (0.0, 0.0, 0.0))


if __name__ == "__main__":
    addon_harness.run(globals())
