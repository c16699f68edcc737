"""Undo of the add-on's operators. Blender keeps no undo stack in background
mode, so ctest runs this one in a real window under Xvfb (xvfb-run)."""

import array
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402


def heights(name):
    mesh = bpy.data.objects[name].data
    co = array.array("f", [0.0]) * (3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    return co[2::3]


class UndoTest(unittest.TestCase):
    def test_undo_removes_the_added_terrain_and_its_mesh(self):
        # Only the add is checked: steps pushed by later operators called from a
        # start-up script are not kept apart by Blender's memfile undo, so the
        # regenerate step is not covered here.
        self.assertFalse(bpy.app.background, "run this test with a window (xvfb-run)")
        meshes = len(bpy.data.meshes)
        bpy.ops.ed.undo_push(message="before the terrain")
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(levels=4, seed=1), {"FINISHED"})
        name = bpy.context.active_object.name
        self.assertEqual(len(heights(name)), 17 * 17)
        self.assertEqual(bpy.ops.ed.undo(), {"FINISHED"})
        self.assertNotIn(name, bpy.data.objects)
        self.assertEqual(len(bpy.data.meshes), meshes)

    def test_undo_removes_an_eroded_terrain_and_its_maps(self):
        # Adding with an erosion preset is one undo step like any add: undo takes
        # the object, its mesh (with the erosion attributes) away.
        meshes = len(bpy.data.meshes)
        bpy.ops.ed.undo_push(message="before the eroded terrain")
        self.assertEqual(bpy.ops.mesh.fracterra_terrain_add(levels=5, seed=2, erode_preset="SCREE"), {"FINISHED"})
        obj = bpy.context.active_object
        name = obj.name
        self.assertIn("fracterra_flow", obj.data.attributes)
        self.assertEqual(bpy.ops.ed.undo(), {"FINISHED"})
        self.assertNotIn(name, bpy.data.objects)
        self.assertEqual(len(bpy.data.meshes), meshes)


if __name__ == "__main__":
    addon_harness.run(globals())
