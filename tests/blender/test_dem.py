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


if __name__ == "__main__":
    addon_harness.run(globals())
