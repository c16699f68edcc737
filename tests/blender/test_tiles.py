# SPDX-License-Identifier: GPL-3.0-or-later
"""File > Import > fracterra tile set in real Blender, through the installed
add-on: a window of a 4 x 4 tile set at a level of detail, as one mesh and as
one object per tile; north up; neighbouring tile objects share their edge
vertices; a bad window is an error report, not a traceback. Build Tile Set
on an eroded terrain object writes the object's own terrain (the same
heights and colours at Finer By 0, the same grid at its level of detail one
level finer), and the imported pieces carry the whole set's splat colours."""

import array
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402

SETTINGS = {"method": "MIDPOINT", "levels": 7, "hurst": 0.7, "seed": 5}  # 129^2
TILE = 32


def coords(obj):
    co = array.array("f", [0.0]) * (3 * len(obj.data.vertices))
    obj.data.vertices.foreach_get("co", co)
    return [(obj.location.x + co[3 * i], obj.location.y + co[3 * i + 1], co[3 * i + 2])
            for i in range(len(obj.data.vertices))]


class TilesImportTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        tiles = addon_harness.submodule("core.tiles")
        cls.dir = os.path.join(tempfile.mkdtemp(prefix="ft_tiles_"), "set")
        # The tile set written in-process (the Dask driver's task, without Dask).
        with tiles.TileSet.open(SETTINGS, cls.dir, TILE) as ts:
            lo, hi = ts.height_range()
            for row in range(4):
                for col in range(4):
                    ts.record(*tiles.write_tile(col, row, SETTINGS, None, TILE, "png16", lo, hi, cls.dir))
            ts.finish()
        cls.step = (hi - lo) / 65535
        core = addon_harness.submodule("core")
        cls.whole = core.generate_terrain(SETTINGS)
        cls.values = cls.whole.to_array()
        cls.spacing = tiles.manifest(cls.dir)["sample_spacing"]

    def setUp(self):
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)

    def manifest(self):
        return os.path.join(self.dir, "manifest.json")

    def test_one_mesh_at_a_level_of_detail_is_the_coarser_terrain_north_up(self):
        self.assertEqual(bpy.ops.import_scene.fracterra_tiles(filepath=self.manifest(), lod=2), {"FINISHED"})
        obj = bpy.context.active_object
        self.assertEqual(len(obj.data.vertices), 33 * 33)
        pts = coords(obj)
        # North (row 0 of the set) is +y: the vertex at the largest y and smallest x is sample (0, 0);
        # every vertex is sample (4 i, 4 j) of the whole, to half a 16-bit step.
        half = 16 * self.spacing * 4
        for x, y, z in pts:
            i, j = round((x + half) / (4 * self.spacing)), round((half - y) / (4 * self.spacing))
            self.assertAlmostEqual(z, self.values[(4 * j) * 129 + 4 * i], delta=0.5 * self.step + 1e-5)
        nw = max(pts, key=lambda p: (p[1], -p[0]))
        self.assertAlmostEqual(nw[2], self.values[0], delta=0.5 * self.step + 1e-5)

    def test_object_per_tile_meets_its_neighbours_without_cracks(self):
        self.assertEqual(bpy.ops.import_scene.fracterra_tiles(filepath=self.manifest(), x0=16, y0=16, width=80,
                                                              height=80, mode="TILES"), {"FINISHED"})
        objs = [o for o in bpy.data.objects if o.type == "MESH"]
        self.assertEqual(len(objs), 9)  # columns/rows 16..95 touch 3 x 3 tiles
        # Every vertex on a shared edge is in two objects at the same place with the same height.
        seen = {}
        shared = 0
        for obj in objs:
            for x, y, z in coords(obj):
                key = (round(2 * x / self.spacing), round(2 * y / self.spacing))  # half-sample centring
                if key in seen:
                    shared += 1
                    self.assertAlmostEqual(seen[key], z, places=6)
                seen[key] = z
        self.assertEqual(len(seen), 80 * 80)  # together they are the window, nothing missing
        self.assertEqual(shared, 2 * 80 * 2 + 4)  # 2 seams across and 2 down; their 4 crossings are in 4 objects

    def test_tile_objects_are_shaded_like_one_mesh_without_seams(self):
        # Blender's own smooth normals of a tile object see only its own faces:
        # at a shared edge the two sides differed (a seam line under a low
        # sun). Custom normals from the set's samples around each vertex make
        # both sides, and the one-mesh import, agree.
        def normals(obj):
            mesh = obj.data
            if hasattr(mesh, "calc_normals_split"):
                mesh.calc_normals_split()
            per_vertex = {}
            for loop in mesh.loops:
                per_vertex[loop.vertex_index] = tuple(loop.normal)
            co = coords(obj)
            return {(round(2 * co[i][0] / self.spacing), round(2 * co[i][1] / self.spacing)): n
                    for i, n in per_vertex.items()}

        window = dict(filepath=self.manifest(), x0=16, y0=16, width=80, height=80)
        self.assertEqual(bpy.ops.import_scene.fracterra_tiles(mode="MESH", **window), {"FINISHED"})
        mesh_obj = bpy.context.active_object
        whole = normals(mesh_obj)
        # Oriented right: Blender's own normals from the faces estimate the same surface
        # normals (on this rough 129^2 terrain they agree to a mean cosine of 0.976);
        # custom normals with the sign of a gradient wrong, mirrored in x or y, agree to 0.70-0.72.
        custom = self.vertex_normals(mesh_obj)
        own = [tuple(v.normal) for v in mesh_obj.data.vertices]

        def mean_cos(flip_x, flip_y):
            return sum(a[0] * b[0] * flip_x + a[1] * b[1] * flip_y + a[2] * b[2] for a, b in zip(own, custom)) / len(own)

        self.assertGreater(mean_cos(1, 1), 0.95)
        self.assertGreater(mean_cos(1, 1), mean_cos(-1, 1) + 0.1)
        self.assertGreater(mean_cos(1, 1), mean_cos(1, -1) + 0.1)
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)
        self.assertEqual(bpy.ops.import_scene.fracterra_tiles(mode="TILES", **window), {"FINISHED"})
        # Blender stores custom normals as 16-bit angles in each loop's own frame: the two
        # sides of a seam agree to some 1e-5 (on the 0.3.0 terrain up to 2.5e-3 at its steepest
        # seam vertices: each side is within the one mesh's 5e-3, encoded in its own loop
        # frame), the one mesh to 3e-3 (at 7 of 6724 vertices above 2e-4). Without the
        # custom normals the two sides differ by up to 0.24.
        seam, first = 0, {}
        for obj in [o for o in bpy.data.objects if o.type == "MESH"]:
            for key, n in normals(obj).items():
                for a, b in zip(n, whole[key]):
                    self.assertAlmostEqual(a, b, delta=5e-3)
                if key in first:
                    for a, b in zip(n, first[key]):
                        self.assertAlmostEqual(a, b, delta=5e-3)
                first.setdefault(key, n)
                seam += 1
        self.assertEqual(seam, 80 * 80 + 2 * 80 * 2 + 4)

    def vertex_normals(self, obj):
        """Each vertex's loop normal (the custom one), in vertex order."""
        mesh = obj.data
        if hasattr(mesh, "calc_normals_split"):
            mesh.calc_normals_split()
        out = [None] * len(mesh.vertices)
        for loop in mesh.loops:
            out[loop.vertex_index] = tuple(loop.normal)
        return out

    def test_a_window_outside_the_set_is_an_error_report(self):
        with self.assertRaises(RuntimeError) as cm:
            bpy.ops.import_scene.fracterra_tiles(filepath=self.manifest(), x0=120, width=20)
        self.assertIn("not inside", str(cm.exception))
        self.assertNotIn("Traceback", str(cm.exception))


def attribute(obj, name="fracterra_color", width=4):
    layer = obj.data.attributes[name]
    out = array.array("f", [0.0]) * (width * len(obj.data.vertices))
    layer.data.foreach_get("color", out)
    return out


class BuildTileSetTest(unittest.TestCase):
    """File > Export > Build Tile Set on an eroded terrain (Rugged Mountains, 65^2)."""

    def setUp(self):
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(levels=6, seed=5, erode_preset="LAND"), {"FINISHED"})
        self.terrain = bpy.context.active_object
        self.folder = os.path.join(tempfile.mkdtemp(prefix="ft_build_tiles_"), "set")

    def build(self, **kw):
        self.terrain.select_set(True)
        bpy.context.view_layer.objects.active = self.terrain
        result = bpy.ops.export_scene.fracterra_tiles(filepath=self.folder + os.sep, **kw)
        self.assertEqual(result, {"FINISHED"})
        imported = bpy.context.active_object
        self.assertIsNot(imported, self.terrain)
        return imported

    def test_finer_by_zero_is_the_objects_own_terrain_heights_and_colours(self):
        # Every tile is a window of what the object's build made: the same float heights (tiff tiles),
        # and the same colours (the whole set's splat rules: its range, area, deposits and flow).
        imported = self.build(finer_by=0, tile=16, tile_format="tiff")
        a = array.array("f", [0.0]) * (3 * len(self.terrain.data.vertices))
        b = array.array("f", [0.0]) * (3 * len(imported.data.vertices))
        self.terrain.data.vertices.foreach_get("co", a)
        imported.data.vertices.foreach_get("co", b)
        self.assertEqual(len(a), len(b))
        self.assertEqual(max(abs(x - y) for x, y in zip(a[2::3], b[2::3])), 0.0)
        ca, cb = attribute(self.terrain), attribute(imported)
        self.assertLess(max(abs(x - y) for x, y in zip(ca, cb)), 1e-6)
        self.assertEqual(imported.data.materials[0].name.split(".")[0], "Fracterra Terrain")
        manifest = addon_harness.submodule("core.tiles").manifest(self.folder)
        self.assertEqual(manifest["erosion"]["preset"], "land")
        self.assertEqual(manifest["columns"], 4)

    def test_finer_by_one_has_twice_the_samples_and_imports_at_the_objects_grid(self):
        imported = self.build(finer_by=1, tile=32)
        manifest = addon_harness.submodule("core.tiles").manifest(self.folder)
        self.assertEqual(manifest["width"], 129)
        self.assertEqual(len(imported.data.vertices), len(self.terrain.data.vertices))  # imported at lod 1


if __name__ == "__main__":
    addon_harness.run(globals())
