# SPDX-License-Identifier: GPL-3.0-or-later
"""With no usable libfracterra.so the add-on still registers, and its
operators answer with a report saying what to do (ctest points
FRACTERRA_LIBRARY at a file that does not exist)."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402


class MissingLibraryTest(unittest.TestCase):
    def test_addon_registers_and_reports_what_to_do(self):
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add.get_rna_type().identifier,
                         "MESH_OT_fracterra_terrain_add")
        import fracterra.core as core
        ok, message = core.status()
        self.assertFalse(ok)
        self.assertIn("FRACTERRA_LIBRARY", message)
        with self.assertRaises(RuntimeError) as cm:
            bpy.ops.mesh.fracterra_terrain_add(levels=3)
        text = str(cm.exception)
        self.assertNotIn("Traceback", text)
        self.assertIn("libfracterra.so not found", text)
        self.assertIn("fracterra_blender_addon", text)
        self.assertEqual(len([o for o in bpy.data.objects if o.name.startswith("Fractal")]), 0)


if __name__ == "__main__":
    addon_harness.run(globals())
