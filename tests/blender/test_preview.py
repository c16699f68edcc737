# SPDX-License-Identifier: GPL-3.0-or-later
"""Preview and Final (issue 24, part 4): Auto Update edits a terrain at its
Preview level, Regenerate (Build Final) and a command-line render build its
Final level, and the two are the same terrain: at the nodes they share, the
Preview's vertices lie where the Final's do.

That needs a resolution-independent library (issue 24, part 2): midpoint
levels L equal levels L + k at the shared nodes, bit for bit, and erosion that
depends on world units, not on grid steps. Each test first asks the library
itself (no add-on involved) whether it has that property, and is skipped,
naming what is missing, when it does not."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402
import numpy as np  # noqa: E402

PREVIEW, FINAL = 5, 7  # 33^2 and 129^2: every 4th Final node is a Preview node
STRIDE = 2 ** (FINAL - PREVIEW)


def core():
    return addon_harness.submodule("core")


def terrain_module():
    return addon_harness.submodule("blender.build.terrain")


def objects_module():
    return addon_harness.submodule("blender.build.objects")


def grid(obj):
    """The mesh's vertices as an (ny, nx, 3) array."""
    mesh = obj.data
    co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    side = int(round(len(mesh.vertices) ** 0.5))
    return co.reshape(side, side, 3)


def library_heights(values, levels):
    with core().generate_terrain({**values, "levels": levels}) as hf:
        return np.frombuffer(hf.to_array(), dtype=np.float32).reshape(hf.height, hf.width)


def library_eroded(values, levels, preset):
    """The library's terrain at `levels` eroded by `preset` (core.erosion, as
    `fracterra erode --preset`), no add-on code involved."""
    erosion = addon_harness.submodule("core.erosion")
    with core().generate_terrain({**values, "levels": levels}) as hf:
        eroded, _maps = erosion.erode(hf, preset=preset, threads=1, maps=False)
    with eroded:
        return np.frombuffer(eroded.to_array(), dtype=np.float32).reshape(eroded.height, eroded.width)


def settings(**changes):
    values = core().params.defaults()
    values.update(changes)
    return values


def add_terrain(**kw):
    result = bpy.ops.mesh.fracterra_terrain_add(**kw)
    assert result == {"FINISHED"}, result
    return bpy.context.active_object


class PreviewFinalTest(unittest.TestCase):
    def setUp(self):
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)

    def require_midpoint_resolution_independence(self, values):
        coarse, fine = library_heights(values, PREVIEW), library_heights(values, FINAL)
        if not np.array_equal(coarse, fine[::STRIDE, ::STRIDE]):
            differ = float(np.abs(coarse - fine[::STRIDE, ::STRIDE]).max())
            self.skipTest(f"the library's midpoint method is not resolution independent yet (levels {PREVIEW} "
                          f"and {FINAL} differ by up to {differ:.3f} at shared nodes): issue 24 part 2, "
                          f"branch `res`")

    def test_auto_update_builds_the_preview_and_regenerate_the_final(self):
        obj = add_terrain(levels=FINAL, preview_levels=PREVIEW, seed=3)
        s = obj.fracterra_terrain
        self.assertEqual(objects_module().mesh_level(obj), ("Final", 129, 129))
        s.auto_update = True
        s.seed = 4  # Auto Update: the Preview
        self.assertEqual(s.last_error, "")
        self.assertEqual(objects_module().mesh_level(obj), ("Preview", 33, 33))
        s.auto_update = False
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertEqual(objects_module().mesh_level(obj), ("Final", 129, 129))

    def test_raised_levels_leave_the_mesh_shown_as_what_it_is(self):
        """With Auto Update off, raising Detail Levels changes the settings, not
        the mesh: the sidebar still says the mesh is the Final it was built as
        (it said "Mesh: edited, not its grid" until a Regenerate)."""
        obj = add_terrain(levels=FINAL, preview_levels=PREVIEW, seed=3)
        s = obj.fracterra_terrain
        s.auto_update = False
        s.levels = FINAL + 1
        self.assertEqual(objects_module().mesh_level(obj), ("Final", 129, 129))
        self.assertEqual(objects_module().terrain_grid_size(obj), (129, 129))

    def test_the_preview_is_the_final_at_their_shared_nodes(self):
        """Raise the levels of a terrain: at every node the Preview has, the Final
        has the same vertex (x, y and height)."""
        values = settings(seed=7, preview_levels=PREVIEW)
        self.require_midpoint_resolution_independence(values)
        obj = add_terrain(levels=FINAL, preview_levels=PREVIEW, seed=7)
        final = grid(obj)
        terrain_module().regenerate_object(obj, bpy.context, preview=True)
        preview = grid(obj)
        self.assertEqual(preview.shape, (33, 33, 3))
        np.testing.assert_array_equal(preview, final[::STRIDE, ::STRIDE])

    def test_an_eroded_preview_is_the_eroded_final_at_their_shared_nodes(self):
        """With erosion the two cannot be equal bit for bit; issue 24 asks a
        correlation of at least 0.98 of the eroded heights at shared nodes."""
        values = settings(seed=7)
        self.require_midpoint_resolution_independence(values)
        coarse, fine = library_eroded(values, PREVIEW, "scree"), library_eroded(values, FINAL, "scree")
        r = float(np.corrcoef(coarse.ravel(), fine[::STRIDE, ::STRIDE].ravel())[0, 1])
        if r < 0.98:
            self.skipTest(f"the library's erosion is not resolution independent yet (levels {PREVIEW} and "
                          f"{FINAL} correlate {r:.3f} < 0.98 at shared nodes): issue 24 part 2, branch `emodel`")
        obj = add_terrain(levels=FINAL, preview_levels=PREVIEW, seed=7, erode_preset="SCREE")
        final = grid(obj)
        terrain_module().regenerate_object(obj, bpy.context, preview=True)
        preview = grid(obj)
        np.testing.assert_array_equal(preview[..., :2], final[::STRIDE, ::STRIDE, :2])
        r = float(np.corrcoef(preview[..., 2].ravel(), final[::STRIDE, ::STRIDE, 2].ravel())[0, 1])
        self.assertGreaterEqual(r, 0.98)

    def test_the_preview_is_built_from_the_same_settings(self):
        """Independent of the library's resolution independence: the Preview is the
        library's terrain at Preview Levels with every other setting the Final's,
        its vertices at the Final's x and y."""
        obj = add_terrain(levels=FINAL, preview_levels=PREVIEW, seed=11, hurst=0.6)
        final = grid(obj)
        terrain_module().regenerate_object(obj, bpy.context, preview=True)
        preview = grid(obj)
        want = library_heights(core().params.values_of(obj.fracterra_terrain), PREVIEW)
        np.testing.assert_array_equal(preview[..., 2], want)
        np.testing.assert_array_equal(preview[..., :2], final[::STRIDE, ::STRIDE, :2])

    def test_a_command_line_render_builds_the_final(self):
        obj = add_terrain(levels=FINAL, preview_levels=PREVIEW, seed=5)
        terrain_module().regenerate_object(obj, bpy.context, preview=True)
        self.assertEqual(objects_module().mesh_level(obj)[0], "Preview")
        scene = bpy.context.scene
        bpy.ops.object.camera_add(location=(0, -15, 10), rotation=(0.9, 0, 0))
        scene.camera = bpy.context.active_object
        scene.render.engine = "BLENDER_WORKBENCH"
        scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 32, 24, 100
        bpy.ops.render.render()
        self.assertEqual(objects_module().mesh_level(bpy.data.objects[obj.name]), ("Final", 129, 129))


if __name__ == "__main__":
    addon_harness.run(globals())
