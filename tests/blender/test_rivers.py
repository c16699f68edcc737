# SPDX-License-Identifier: GPL-3.0-or-later
"""Rivers and Lakes of a terrain in real Blender: the operator traces them
through the library's pipeline, so they are the rivers `fracterra terrain
--rivers` writes for the same settings (the CLI, another front end), a tiling
terrain's included; rivers are curves whose bevel follows the width, lakes
and the sea flat meshes at their levels, all with the water material and
parented to the terrain; Regenerate retraces them without duplicating
anything; the coastline and the water objects edit their terrain from the
sidebar; the default lightning bolt over a terrain strikes its surface.
No lake or sea face lies within the minimum water depth (1% of the relief)
of the ground Blender draws under it, on the default terrain and three
seeds, and the rivers lie on or in their carved beds."""

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
from mathutils.bvhtree import BVHTree  # noqa: E402

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
        """The network is the CLI's, polyline for polyline, point for point, and the curve's
        splines are its lines as drawn (the library's ribbon lines: cut where a ribbon would
        reach into a lake), in the terrain's frame."""
        settings = terrain.fracterra_terrain
        values = core().params.values_of(settings)
        preset = values.get("erode_preset", "NONE")  # as blender/build/erosion.py builds it
        eroded = preset not in ("NONE", "CUSTOM")
        hf, _maps, water = core().build_terrain_rivers(values, core().params.RIVERS_PARAMS,
                                                       erosion=values if eroded else None,
                                                       preset=preset if eroded else "NONE")
        hf.close()
        half = 0.5 * settings.world_size
        k = 1.0  # the network's world units are the terrain's local units (x spans World Size)

        def lines(xyz, radii, offsets):
            return [(xyz[a:b], radii[a:b]) for a, b in zip(offsets[:-1], offsets[1:]) if b - a >= 2]

        drawn = lines(water.ribbon_xyz, water.ribbon_radii, water.ribbon_offsets)
        got = spline_points(rivers.data)
        self.assertEqual(len(got), len(drawn))
        for (co, r), (pts, radii) in zip(got, drawn):
            np.testing.assert_allclose(co[:, 0], pts[:, 0] * k - half, atol=1e-4)
            np.testing.assert_allclose(co[:, 1], pts[:, 1] * k - half, atol=1e-4)
            np.testing.assert_allclose(co[:, 2], pts[:, 2], atol=1e-4)
            np.testing.assert_allclose(r, radii * k, rtol=1e-5)
        try:
            want = cli_rivers(settings)["polylines"]
        except unittest.SkipTest:  # no CLI (Blender 4.3's root): the rest of the test still runs
            return
        whole = lines(water.xyz, water.radii, water.offsets)
        self.assertEqual(len(whole), len([p for p in want if len(p["points"]) >= 2]))
        for (pts, radii), line in zip(whole, (p for p in want if len(p["points"]) >= 2)):
            np.testing.assert_allclose(pts, np.array(line["points"], dtype=np.float64), atol=1e-4)
            np.testing.assert_allclose(radii, np.array(line["radii"]), rtol=1e-5)

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
        # Just over the minimum depth (1% of the relief) above the highest sea
        # cell, cut to where it is deeper: the sea is the terrain's own (the
        # landform flattened 20% of the samples), and its water covers the
        # samples more than the minimum depth under it: measured 24% while a
        # 65^2 terrain eroded on its own grid, 30.2% since it erodes on the
        # model grid as its Final does (0.6.0), 36.4% since the carve keeps
        # the ground under every cell a river's ribbon covers under its water
        # (the coast's river beds, cut down to the sea's level, count).
        heights = np.array([v.co.z for v in terrain.data.vertices])
        below = np.mean(heights < z[0] - 0.01 * np.ptp(heights))
        self.assertGreater(below, 0.18)
        self.assertLessEqual(below, 0.40)
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


def ground_under(terrain, points):
    """The height of terrain's surface as Blender draws it (its triangles:
    BVHTree over the evaluated mesh, a ray straight down) under each local
    point (n, 3); NaN where no triangle is under it."""
    tree = BVHTree.FromObject(terrain, bpy.context.evaluated_depsgraph_get())
    top = max(v.co.z for v in terrain.data.vertices) + 1.0
    down = Vector((0.0, 0.0, -1.0))
    out = np.full(len(points), np.nan)
    half = 0.5 * terrain.fracterra_terrain.world_size - 1e-5  # a ray on the border may slip past it
    for k, (x, y, _z) in enumerate(points):
        hit = tree.ray_cast(Vector((min(max(x, -half), half), min(max(y, -half), half), top)), down)[0]
        if hit is not None:
            out[k] = hit.z
    return out


def face_points(mesh):
    """Every vertex and every face's centroid (n, 3) of a mesh, local frame."""
    co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3).astype(np.float64)
    idx = np.empty(len(mesh.loops), dtype=np.int32)
    mesh.loops.foreach_get("vertex_index", idx)
    tri = idx.reshape(-1, 3)  # the water meshes are triangles
    return np.concatenate([co, co[tri].mean(axis=1)])


class WaterDepthTest(unittest.TestCase):
    """The water depth rule: every lake and sea vertex and face centre stands
    more than the network's minimum depth (1% of the relief by default) over
    the ground under it. Vertices on a shoreline lie at exactly that depth
    (the cut), so the bound is the depth less float32's rounding of heights
    of a few metres (1e-5 m); a face's centre is deeper. Before: on the default
    terrain (seed 13) all 18 627 lake faces lay at z = 0 on ground at z = 0.
    A sea over the floor the landform flattened stands 1.1 x the minimum
    depth over it."""

    def setUp(self):
        clear_scene()

    def check(self, terrain):
        core_ = core()
        settings = terrain.fracterra_terrain
        values = core_.params.values_of(settings)
        hf, _maps, water = core_.build_terrain_rivers(values, core_.params.RIVERS_PARAMS)
        heights = hf.to_array()
        hf.close()
        relief = float(np.ptp(heights))
        self.assertAlmostEqual(water.min_depth, 0.01 * relief, delta=1e-3 * relief, msg="1% of the relief")
        made = kinds(terrain)
        checked = 0
        for kind in ("LAKES", "SEA"):
            if kind not in made:
                continue
            pts = face_points(made[kind].data)
            depth = pts[:, 2] - ground_under(terrain, pts)
            self.assertFalse(np.isnan(depth).any(), f"{kind}: water off the terrain")
            shallow = depth < water.min_depth - 1e-5
            self.assertEqual(int(shallow.sum()), 0, f"{kind}: {shallow.sum()} of {len(depth)} points within "
                             f"{water.min_depth:.4f} of the ground (least depth {depth.min():.5f})")
            checked += len(depth)
        return checked

    def test_no_water_face_lies_within_the_minimum_depth_of_the_ground(self):
        # The default terrain (seed 13, its Rivers and Lakes) and three more
        # seeds (at 129^2: the test's time).
        checked = 0
        for seed, levels in ((13, None), (1, 7), (2, 7), (3, 7)):
            clear_scene()
            args = {"seed": seed, "rivers": True} | ({"levels": levels} if levels else {})
            self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(**args), {"FINISHED"})
            checked += self.check(bpy.context.active_object)
        self.assertGreater(checked, 1000, "the test needs water")

    def test_a_sea_stands_over_its_flattened_floor(self):
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(levels=7, seed=5, rivers=True, sea="FRACTION",
                                                            sea_fraction=0.3), {"FINISHED"})
        terrain = bpy.context.active_object
        self.assertIn("SEA", kinds(terrain))
        self.assertGreater(self.check(terrain), 100)

    def test_no_sliver_faces(self):
        # POV-Ray refuses a mesh with a face of zero area ("face N has zero
        # area") and the sea went missing from its render.
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(levels=7, seed=5, rivers=True, sea="FRACTION",
                                                            sea_fraction=0.3), {"FINISHED"})
        terrain = bpy.context.active_object
        cell = terrain.fracterra_terrain.world_size / 2 ** 7
        for kind in ("LAKES", "SEA"):
            mesh = kinds(terrain).get(kind)
            if mesh is None:
                continue
            areas = np.array([p.area for p in mesh.data.polygons])
            self.assertGreater(areas.min(), 1e-6 * cell * cell, kind)


if __name__ == "__main__":
    addon_harness.run(globals())
