# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on on a system without GDAL (the library opens the system's GDAL at
run time and carries none): File > Import DEM of a GeoTIFF is an error report
that says what to install, with no traceback; every other heightfield format
(PNG, OpenEXR, RAW16, ...) exports and imports as before.

Run where no libgdal is installed (Debian trixie's Blender 4.3 root,
tests/blender/blender4_extension.sh), or with FRACTERRA_GDAL naming a file
that does not exist (ctest's blender_without_gdal): either way the library
must report GDAL missing, which the first test checks.
"""

import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402

# Heightfield formats the library writes and reads without any optional library but OpenEXR.
WITHOUT_GDAL = (".png", ".pgm", ".npy", ".exr", ".raw", ".r16")


class WithoutGdalTest(unittest.TestCase):
    def setUp(self):
        addon_harness.clear_scene()
        self.dir = tempfile.mkdtemp(prefix="ft_nogdal_")
        self.lib = addon_harness.submodule("core.binding").library()

    def test_the_library_reports_gdal_missing(self):
        self.assertEqual(self.lib.ft_has_feature(b"gdal"), 0)
        self.assertNotIn("GeoTIFF", self.lib.ft_heightfield_formats().decode())

    def test_geotiff_import_says_what_to_install(self):
        path = os.path.join(self.dir, "dem.tif")
        with open(path, "wb") as f:
            f.write(b"II*\x00" + bytes(64))  # never read: GDAL is missing
        with self.assertRaises(RuntimeError) as cm:
            bpy.ops.import_scene.fracterra_dem(filepath=path)
        message = str(cm.exception)
        self.assertNotIn("Traceback", message)
        self.assertIn("dem.tif", message)
        self.assertIn("needs GDAL", message)
        self.assertIn("apt install gdal-bin", message)

    def test_geotiff_export_says_what_to_install(self):
        bpy.ops.mesh.fracterra_terrain_add(levels=3)
        with self.assertRaises(RuntimeError) as cm:
            bpy.ops.export_scene.fracterra_heights(filepath=os.path.join(self.dir, "h.tif"))
        self.assertIn("apt install gdal-bin", str(cm.exception))

    def test_the_other_formats_export_and_import(self):
        bpy.ops.mesh.fracterra_terrain_add(levels=3)
        raster = addon_harness.submodule("core.raster")
        for ext in WITHOUT_GDAL:  # the terrain stays active while it exports
            path = os.path.join(self.dir, "h" + ext)
            self.assertEqual(bpy.ops.export_scene.fracterra_heights(filepath=path), {"FINISHED"}, ext)
            with raster.read_heightfield(path) as hf:
                self.assertEqual((hf.width, hf.height), (9, 9), ext)
        for ext in WITHOUT_GDAL:
            path = os.path.join(self.dir, "h" + ext)
            self.assertEqual(bpy.ops.import_scene.fracterra_dem(filepath=path, size=0.0), {"FINISHED"}, ext)
            self.assertEqual(len(bpy.context.active_object.data.vertices), 81, ext)


if __name__ == "__main__":
    addon_harness.run(globals())
