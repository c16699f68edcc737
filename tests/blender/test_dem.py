# SPDX-License-Identifier: GPL-3.0-or-later
"""File > Import DEM as terrain and File > Export terrain heights in real
Blender, through the installed add-on: a DEM written by GDAL comes in north
up at its own size; heights exported in every format read back."""

import array
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402


def raster():
    return addon_harness.submodule("core.raster")


def coords(mesh):
    co = array.array("f", [0.0]) * (3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    return co


def corner_heights(mesh):
    """{'SW', 'SE', 'NW', 'NE'}: z of the mesh's corner vertices (x, y extremes)."""
    co = coords(mesh)
    pts = [tuple(co[i:i + 3]) for i in range(0, len(co), 3)]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    at = {(p[0], p[1]): p[2] for p in pts}
    return {"SW": at[(x0, y0)], "SE": at[(x1, y0)], "NW": at[(x0, y1)], "NE": at[(x1, y1)]}


class DemTest(unittest.TestCase):
    def setUp(self):
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)
        self.dir = tempfile.mkdtemp(prefix="ft_dem_")

    def write_dem(self, name, w=9, h=5):
        # Heights rise to the north (towards the first row): 100 + 10 * (h - 1 - row) + col.
        core = addon_harness.submodule("core")
        values = [100.0 + 10 * (h - 1 - y) + x for y in range(h) for x in range(w)]
        path = os.path.join(self.dir, name)
        with core.Heightfield.from_values(w, h, values) as hf:
            raster().write_heightfield(hf, path)
        return path

    def test_import_puts_north_up_at_the_dems_own_size(self):
        path = self.write_dem("dem.exr")
        self.assertEqual(bpy.ops.import_scene.fracterra_dem(filepath=path, size=0.0), {"FINISHED"})
        obj = bpy.context.active_object
        co = coords(obj.data)
        self.assertEqual(len(co) // 3, 45)
        # The highest vertex is in the north-east corner (+y), the lowest in the south-west (-y).
        top = max(range(45), key=lambda i: co[3 * i + 2])
        low = min(range(45), key=lambda i: co[3 * i + 2])
        self.assertGreater(co[3 * top + 1], 0)
        self.assertLess(co[3 * low + 1], 0)
        self.assertEqual((co[3 * top + 2], co[3 * low + 2]), (148.0, 100.0))

    def test_export_writes_every_format_readable_again(self):
        bpy.ops.mesh.fracterra_terrain_add(levels=3)
        for ext in raster().WRITE_EXTENSIONS:
            path = os.path.join(self.dir, "h" + ext)
            self.assertEqual(bpy.ops.export_scene.fracterra_heights(filepath=path), {"FINISHED"}, ext)
            with raster().read_heightfield(path) as hf:
                self.assertEqual((hf.width, hf.height), (9, 9), ext)

    def test_a_bad_file_is_an_error_report_not_a_traceback(self):
        bad = os.path.join(self.dir, "bad.tif")
        with open(bad, "wb") as f:
            f.write(b"II*\x00garbage")
        with self.assertRaises(RuntimeError) as cm:
            bpy.ops.import_scene.fracterra_dem(filepath=bad)
        self.assertNotIn("Traceback", str(cm.exception))
        self.assertIn("bad.tif", str(cm.exception))

    def add_dem_terrain(self, path, **kw):
        return bpy.ops.mesh.fracterra_terrain_add(method="MIDPOINT", levels=4, reference_source="DEM", levelling=0.0,
                                                  height_offset=0.0, falloff="NONE",  # the raw heights
                                                  reference_file=path, reference_levels=2, **kw)

    def test_a_dem_is_a_terrains_reference_and_stays_editable(self):
        # Not georeferenced: its relief becomes reference_height, lowest point 0.
        path = self.write_dem("ref.exr")
        self.assertEqual(self.add_dem_terrain(path, reference_height=3.0), {"FINISHED"})
        obj = bpy.context.active_object
        self.assertEqual(obj.fracterra_terrain.reference_source, "DEM")
        self.assertEqual(len(obj.data.vertices), 17 * 17)
        # The reference nodes survive exactly: the DEM's lowest corner (south-west) at 0,
        # its highest (north-east, north up) at the relief; the others in between.
        z = corner_heights(obj.data)
        self.assertAlmostEqual(z["SW"], 0.0, places=5)
        self.assertAlmostEqual(z["NE"], 3.0, places=5)
        self.assertAlmostEqual(z["SE"], 3.0 * 8 / 48, places=5)
        self.assertAlmostEqual(z["NW"], 3.0 * 40 / 48, places=5)
        # Re-editable: a new relief regenerates in place.
        obj.fracterra_terrain.reference_height = 6.0
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertAlmostEqual(corner_heights(obj.data)["NE"], 6.0, places=5)

    def test_a_missing_dem_is_an_error_report(self):
        with self.assertRaises(RuntimeError) as cm:
            self.add_dem_terrain(os.path.join(self.dir, "missing.tif"))
        self.assertNotIn("Traceback", str(cm.exception))
        self.assertIn("missing.tif", str(cm.exception))
        with self.assertRaises(RuntimeError) as cm:
            self.add_dem_terrain("")
        self.assertIn("DEM File", str(cm.exception))


if __name__ == "__main__":
    addon_harness.run(globals())
