# SPDX-License-Identifier: GPL-3.0-or-later
"""The finished scene in real Blender: the objects that hang off a terrain
follow it when it re-generates (coastline, rivers, a bolt that struck it),
hiding a terrain hides them, a Final survives an Auto Update edit (kept,
marked out of date, built again or gone back to on request), a new polyline
starts from its own method's base, and every label fits the sidebar.

Heights are checked against an independent bilinear reading of the terrain's
vertex grid: a coastline point lies on a grid edge (marching squares), where
the mesh's surface is the straight line between the edge's two vertices, so
it must be on it to float precision (1 mm is a wide margin on a 10 m terrain).
"""

import array
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402
import numpy as np  # noqa: E402
from mathutils import Vector  # noqa: E402

clear_scene = addon_harness.clear_scene
MM = 1e-3
RIVER_FLAT = 0.3  # the ribbon's height / width (the add-on's build/water.py)


def add_terrain(**kw):
    result = bpy.ops.mesh.fracterra_terrain_add(**kw)
    assert result == {"FINISHED"}, result
    return bpy.context.active_object


def grid(obj):
    """(x (nx,), y (ny,), z (ny, nx)) of a terrain's vertex grid, local frame."""
    co = np.empty(3 * len(obj.data.vertices), dtype=np.float32)
    obj.data.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3).astype(np.float64)
    nx = int(np.sum(co[:, 1] == co[0, 1]))
    z = co[:, 2].reshape(-1, nx)
    return co[:nx, 0], co[::nx, 1], z


def surface(obj, xy):
    """The bilinear height of terrain `obj`'s grid at local points xy (n, 2)."""
    x, y, z = grid(obj)
    c = np.clip(np.interp(xy[:, 0], x, np.arange(len(x))), 0, len(x) - 1)
    r = np.clip(np.interp(xy[:, 1], y, np.arange(len(y))), 0, len(y) - 1)
    c0, r0 = np.minimum(c.astype(int), len(x) - 2), np.minimum(r.astype(int), len(y) - 2)
    fc, fr = c - c0, r - r0
    top = z[r0, c0] * (1 - fc) + z[r0, c0 + 1] * fc
    bottom = z[r0 + 1, c0] * (1 - fc) + z[r0 + 1, c0 + 1] * fc
    return top * (1 - fr) + bottom * fr


def curve_points(obj):
    """Every spline point (n, 3) of a curve object, in its own frame."""
    out = []
    for spline in obj.data.splines:
        co = array.array("f", [0.0]) * (4 * len(spline.points))
        spline.points.foreach_get("co", co)
        out.append(np.array(co, dtype=np.float64).reshape(-1, 4)[:, :3])
    return np.concatenate(out) if out else np.zeros((0, 3))


def curve_radii(obj):
    """Every spline point's radius (n,) of a curve object, in curve_points' order."""
    out = []
    for spline in obj.data.splines:
        r = array.array("f", [0.0]) * len(spline.points)
        spline.points.foreach_get("radius", r)
        out.append(np.array(r, dtype=np.float64))
    return np.concatenate(out) if out else np.zeros(0)


def child(terrain, kind):
    return next(c for c in terrain.children if c.get("fracterra_kind") == kind)


def mod(name):
    return addon_harness.submodule(name)


class ChildrenFollowTest(unittest.TestCase):
    def setUp(self):
        clear_scene()
        bpy.context.scene.cursor.location = (0.0, 0.0, 0.0)

    def coast_error(self, terrain, coast):
        p = curve_points(coast)
        return np.abs(p[:, 2] - surface(terrain, p[:, :2]))

    def test_a_re_edited_terrain_retraces_its_coastline(self):
        # The default mountain (seed 13), its coastline half way up, re-edited
        # as the artist did: seed 21 with Auto Update on.
        terrain = add_terrain(levels=7, seed=13)
        bpy.ops.curve.fracterra_coastline_add(use_quantile=True, quantile=0.5)
        coast = bpy.context.active_object
        self.assertLess(self.coast_error(terrain, coast).max(), MM)
        settings = terrain.fracterra_terrain
        settings.auto_update = True
        settings.seed = 21
        self.assertEqual(settings.last_error, "")
        error = self.coast_error(terrain, coast)
        self.assertLess(error.max(), MM, f"{np.mean(error > 0.02):.0%} of the coastline over 2 cm off the surface")
        # Its level is still the new terrain's median: quantile 0.5 of the new heights.
        z = grid(terrain)[2]
        self.assertAlmostEqual(float(np.median(curve_points(coast)[:, 2])), float(np.quantile(z, 0.5)), delta=0.05)
        # Regenerate (not Auto Update), a new size: the same.
        settings.auto_update = False
        settings.levels, settings.seed = 6, 5
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertLess(self.coast_error(terrain, coast).max(), MM)

    def test_a_coastline_at_the_sea_follows_a_sea_that_moves(self):
        terrain = add_terrain(levels=6, seed=2, sea="FRACTION", sea_fraction=0.4)
        bpy.ops.curve.fracterra_coastline_add()
        coast = bpy.context.active_object
        settings = terrain.fracterra_terrain
        settings.sea_fraction = 0.7
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        sea = grid(terrain)[2].min()
        p = curve_points(coast)
        self.assertTrue(np.all(p[:, 2] - sea < 0.01), (sea, p[:, 2].min(), p[:, 2].max()))
        self.assertLess(self.coast_error(terrain, coast).max(), MM)

    def test_rivers_are_retraced_on_the_new_surface(self):
        terrain = add_terrain(levels=7, seed=13, rivers=True)
        rivers = child(terrain, "RIVERS")
        settings = terrain.fracterra_terrain
        settings.auto_update = True
        settings.seed = 21
        rivers = child(terrain, "RIVERS")
        p, radius = curve_points(rivers), curve_radii(rivers)
        self.assertGreater(len(p), 10)
        # On or in their bed: never above the new surface (lakes hold them
        # higher, at their level: those points are left out).
        lakes = [c for c in terrain.children if c.get("fracterra_kind") == "LAKES"]
        if lakes:
            levels = {round(v.co.z, 5) for v in lakes[0].data.vertices}
            keep = np.array([round(z, 5) not in levels for z in p[:, 2]])
            p, radius = p[keep], radius[keep]
        above = p[:, 2] - surface(terrain, p[:, :2])
        # In their carved bed: the ground under each river is lowered to its
        # depth (a few mm at a channel head, centimetres downstream), so a
        # river point lies on the ground or above it by at most a river's
        # depth (through a pit too small to be a lake a river runs at its
        # brim: a few per cent of the points). The ribbon's clearance is
        # 0.3 x its half width (the point's radius, 0.5-6 cm here), the
        # bed's depth grows with the discharge, and the wide rivers' beds at
        # levels 7 reach 5-7 cm (seed 21: 95th percentile 6.9 cm, median
        # 1.0 cm, 1.1 x the radius). A river left on the old surface is off
        # by decimetres either way; an uncarved one lies flush (median 0).
        self.assertLess(float(np.mean(above < -MM)), 0.05, f"{np.mean(above < -MM):.1%} of the river points under the ground")
        self.assertLess(float(np.mean(above > 0.10)), 0.05, f"{np.mean(above > 0.10):.1%} of the river points 10 cm over their bed")
        self.assertLess(float(np.median(above)), 0.03, "the river floats over its bed")
        self.assertGreater(float(np.median(above - RIVER_FLAT * radius)), -MM, "the ground is under the ribbon's clearance")
        self.assertGreater(float(np.median(above)), 0.2 * MM, "the bed is carved under the river")

    def test_a_bolt_that_struck_the_terrain_strikes_its_new_surface(self):
        terrain = add_terrain(levels=6, seed=13)
        bpy.context.scene.cursor.location = (1.0, 0.5, 0.0)
        self.assertEqual(bpy.ops.curve.fracterra_polyline_add(), {"FINISHED"})
        bolt = bpy.context.active_object
        bpy.context.view_layer.objects.active = terrain
        self.assertEqual(bolt.parent, terrain, "the bolt that struck the terrain is its child")
        length = np.subtract(bolt.fracterra_polyline.start, bolt.fracterra_polyline.end)

        def end_error():
            end = terrain.matrix_world.inverted() @ bolt.matrix_world @ Vector(bolt.fracterra_polyline.end)
            return abs(end.z - surface(terrain, np.array([[end.x, end.y]]))[0])
        self.assertLess(end_error(), 0.02)  # the strike's ray cast meets the triangles, not the bilinear patch
        before = curve_points(bolt)
        terrain.fracterra_terrain.seed = 21
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertLess(end_error(), MM)
        self.assertFalse(np.array_equal(before, curve_points(bolt)), "the bolt was not re-made")
        np.testing.assert_allclose(np.subtract(bolt.fracterra_polyline.start, bolt.fracterra_polyline.end), length,
                                   atol=1e-5, err_msg="the bolt kept its length")

    def test_hiding_a_terrain_hides_its_children(self):
        terrain = add_terrain(levels=6, seed=13, rivers=True, sea="FRACTION", sea_fraction=0.3)
        bpy.ops.curve.fracterra_coastline_add()
        owned = [c for c in terrain.children if c.get("fracterra_kind") != "RIVER_PROFILE"]
        self.assertGreaterEqual(len(owned), 3)
        view_layer = bpy.context.view_layer
        view_layer.update()
        terrain.hide_set(True)
        view_layer.update()
        self.assertEqual([c.name for c in owned if not c.hide_get()], [], "shown while the terrain is hidden")
        terrain.hide_set(False)
        view_layer.update()
        self.assertEqual([c.name for c in owned if c.hide_get()], [], "hidden while the terrain is shown")
        terrain.hide_render = True
        view_layer.update()
        self.assertTrue(all(c.hide_render for c in owned), "rendered while the terrain is not")

    def test_the_sidebar_finds_a_hidden_active_terrain(self):
        terrain = add_terrain(levels=4)
        terrain.hide_set(True)
        panels = mod("blender.ui.panels")
        # The 3D view's context gives no active object for a hidden one.
        hidden = type("C", (), {"active_object": None, "view_layer": bpy.context.view_layer})()
        self.assertTrue(panels.FRACTERRA_PT_terrain.poll(hidden))
        self.assertEqual(mod("blender.build.objects").active_object(hidden), terrain)


class FinalStaysTest(unittest.TestCase):
    def setUp(self):
        clear_scene()

    def edit(self, terrain, **settings):
        s = terrain.fracterra_terrain
        s.auto_update = True
        for k, v in settings.items():
            setattr(s, k, v)
        s.auto_update = False
        self.assertEqual(s.last_error, "")

    def test_an_auto_update_edit_keeps_the_final_and_marks_it_out_of_date(self):
        terrain = add_terrain(levels=8, preview_levels=5, seed=13, rivers=True)
        objects = mod("blender.build.objects")
        final = terrain.data
        heights = grid(terrain)[2].copy()
        self.assertEqual(objects.out_of_date(terrain), [])
        self.edit(terrain, hurst=0.6)
        self.assertEqual(objects.mesh_level(terrain), ("Preview", 33, 33))
        self.assertEqual(terrain.fracterra_final, final, "the Final is kept beside the Preview")
        self.assertEqual(len(final.vertices), 257 * 257)
        np.testing.assert_array_equal(np.array([v.co.z for v in final.vertices]).reshape(257, 257), heights)
        self.assertEqual(objects.out_of_date(terrain), [], "the Preview shown is the settings'")
        self.assertEqual(objects.out_of_date(terrain, final), ["Smoothness"], "the kept Final is marked out of date")
        panels = mod("blender.ui.panels")
        self.assertEqual(panels.build_label(objects.mesh_level(terrain), []), "Build Final")
        # More edits keep the same Final.
        self.edit(terrain, seed=21)
        self.assertEqual(terrain.fracterra_final, final)
        # Build Final rewrites the kept mesh and puts it back; the Preview goes.
        preview = terrain.data.name
        self.assertEqual(bpy.ops.object.fracterra_terrain_regenerate(), {"FINISHED"})
        self.assertEqual(terrain.data, final)
        self.assertIsNone(terrain.fracterra_final)
        self.assertNotIn(preview, bpy.data.meshes)
        self.assertEqual(objects.out_of_date(terrain), [])
        self.assertFalse(np.array_equal(grid(terrain)[2], heights))
        self.assertEqual(len(child(terrain, "RIVERS").data.splines) > 0, True)

    def test_back_to_final_restores_the_mesh_its_water_and_its_settings(self):
        terrain = add_terrain(levels=7, preview_levels=5, seed=13, rivers=True)
        final, heights = terrain.data, grid(terrain)[2].copy()
        rivers = child(terrain, "RIVERS").data
        self.edit(terrain, seed=21)
        self.assertNotEqual(child(terrain, "RIVERS").data, rivers)
        self.assertTrue(bpy.ops.object.fracterra_back_to_final.poll())
        self.assertEqual(bpy.ops.object.fracterra_back_to_final(), {"FINISHED"})
        self.assertEqual(terrain.data, final)
        np.testing.assert_array_equal(grid(terrain)[2], heights)
        self.assertEqual(terrain.fracterra_terrain.seed, 13)
        self.assertEqual(child(terrain, "RIVERS").data, rivers)
        self.assertEqual(mod("blender.build.objects").out_of_date(terrain), [])
        self.assertFalse(bpy.ops.object.fracterra_back_to_final.poll())

    def test_a_changed_seed_without_auto_update_is_out_of_date(self):
        terrain = add_terrain(levels=5)
        objects, panels = mod("blender.build.objects"), mod("blender.ui.panels")
        terrain.fracterra_terrain.seed = 99
        self.assertEqual(objects.mesh_level(terrain), ("Final", 33, 33))
        self.assertEqual(objects.out_of_date(terrain), ["Seed"])
        self.assertEqual(panels.build_label(objects.mesh_level(terrain), ["Seed"]), "Build Final")
        terrain.fracterra_terrain.preview_levels = 3  # not what a Final is built from
        self.assertEqual(objects.out_of_date(terrain), ["Seed"])

    def test_rivers_are_traced_at_the_level_shown(self):
        terrain = add_terrain(levels=8, preview_levels=5, seed=13)
        self.edit(terrain, hurst=0.6)
        self.assertEqual(len(terrain.data.vertices), 33 * 33)
        self.assertEqual(bpy.ops.object.fracterra_rivers(), {"FINISHED"})
        self.assertEqual(len(terrain.data.vertices), 33 * 33, "Rivers and Lakes built the Final unasked")
        self.assertTrue(terrain.fracterra_terrain.rivers)
        self.assertIsNotNone(terrain.fracterra_final)


class PolylineDefaultsTest(unittest.TestCase):
    def setUp(self):
        clear_scene()
        bpy.context.scene.cursor.location = (0.0, 0.0, 0.0)

    def test_a_koch_curve_after_a_bolt_lies_flat(self):
        self.assertEqual(bpy.ops.curve.fracterra_polyline_add(), {"FINISHED"})  # the bolt
        self.assertEqual(bpy.ops.curve.fracterra_polyline_add(method="KOCH", depth=3), {"FINISHED"})
        koch = bpy.context.active_object
        p = curve_points(koch)
        self.assertEqual(float(np.ptp(p[:, 2])), 0.0, "the Koch curve is not flat")
        self.assertAlmostEqual(float(np.ptp(p[:, 0])), 10.0, places=4)
        self.assertGreater(float(np.ptp(p[:, 1])), 1.0, "edge-on: a bar")
        # And a bolt after the Koch curve falls again.
        self.assertEqual(bpy.ops.curve.fracterra_polyline_add(method="FPL3D"), {"FINISHED"})
        s = bpy.context.active_object.fracterra_polyline
        self.assertEqual((tuple(s.start), tuple(s.end)), ((0.0, 0.0, 10.0), (0.0, 0.0, 0.0)))


class PlanetDefaultsTest(unittest.TestCase):
    def test_the_default_planet_shows_its_relief(self):
        # Its land must rise over 1 % of the radius above the sea for the default
        # view to shade it (at Exaggeration 20 it rose 0.4 %: a flat disc).
        clear_scene()
        self.assertEqual(bpy.ops.mesh.fracterra_planet_add(level=5), {"FINISHED"})
        planet = bpy.context.active_object
        co = np.array([v.co for v in planet.data.vertices])
        r = np.linalg.norm(co, axis=1) / planet.fracterra_planet.scene_radius
        sea = np.linalg.norm(child(planet, "SEA").data.vertices[0].co) / planet.fracterra_planet.scene_radius
        self.assertGreater(r.max() - r.min(), 0.01, (r.min(), r.max(), sea))


class WidthLayout:
    """Stands in for a UILayout in background mode: records what each label,
    field and button would show, and how much of the row it gets (a split's
    factor), so the test can measure it."""

    def __init__(self, log, share=1.0, split=False):
        self.log, self.share, self.use_property_split = log, share, split
        self.use_property_decorate, self.alert, self.enabled, self.active = False, False, True, True

    def _child(self, share=None):
        return WidthLayout(self.log, self.share if share is None else share, self.use_property_split)

    def column(self, **_kw):
        return self._child()

    row = box = column_flow = grid_flow = column

    def split(self, factor=0.5, **_kw):
        return WidthLayout(self.log, self.share * factor, self.use_property_split)

    def label(self, text="", icon="NONE", **_kw):
        self.log.append(("label", text, self.share, icon))

    def prop(self, data, name, text=None, **_kw):
        self.log.append(("prop", text, self.share, (data, name, self.use_property_split)))

    def prop_search(self, data, name, *_args, text=None, **_kw):
        self.prop(data, name, text=text)

    def operator(self, idname, text=None, **_kw):
        self.log.append(("operator", text, self.share, idname))
        return type("OperatorProperties", (), {})()

    def separator(self, **_kw):
        pass


def value_text(data, name):
    """What a numeric field shows beside its label: the value at the field's
    precision and, for a length, its unit (Blender's own formatting, roughly)."""
    prop = data.bl_rna.properties[name]
    value = getattr(data, name)
    if prop.type == "INT":
        return str(value)
    digits = max(getattr(prop, "precision", 2), 2)
    unit = " m" if prop.unit == "LENGTH" else (" deg" if prop.unit == "ROTATION" else "")
    return f"{value:.{digits}f}{unit}"


class LabelWidthTest(unittest.TestCase):
    """Every label the sidebar panels draw fits the default sidebar width at
    Blender's default UI scale (widgets.SIDEBAR_CHARACTERS: 30 characters a
    row, measured on screenshots; an icon takes widgets.ICON_CHARACTERS of
    them): a label row whole, a field's label with its
    value, a split row's label in its share. Drawn for every terrain method,
    every landform and source choice, eroded, with rivers, and for a planet
    and a polyline."""

    def texts(self, draw, *args):
        log = []
        draw(type("P", (), {"layout": WidthLayout(log)})(), *args)
        return log

    def too_long(self, log):
        limit = mod("blender.common.widgets").SIDEBAR_CHARACTERS
        bad = []
        for kind, text, share, extra in log:
            if kind == "operator":
                idname = extra
                category, name = idname.split(".")
                shown = text if text is not None else getattr(getattr(bpy.ops, category), name).get_rna_type().name
                room = limit * share
            elif kind == "label":
                # An icon (BLANK1 too: the wrapped lines under an icon) takes its characters.
                icon_room = 0 if extra == "NONE" else mod("blender.common.widgets").ICON_CHARACTERS
                shown, room = text, limit * share - icon_room
            else:
                data, name, split = extra
                prop = data.bl_rna.properties[name]
                shown = prop.name if text is None else text
                if not shown:
                    continue
                room = limit * share * (0.4 if split else 1.0)
                if prop.type in ("INT", "FLOAT") and not getattr(prop, "is_array", False) and not split:
                    shown = f"{shown}  {value_text(data, name)}"  # label and value share the field
            if len(shown) > room:
                bad.append(f"{shown!r} ({len(shown)} > {room:.0f})")
        return bad

    def test_sidebar_labels_fit(self):
        clear_scene()
        panels, rivers = mod("blender.ui.panels"), mod("blender.ui.rivers_panel")
        terrain = add_terrain(levels=5, preview_levels=3, rivers=True)
        s = terrain.fracterra_terrain
        s.auto_update = True
        s.seed = 2  # a Preview with the Final kept beside it
        s.auto_update = False
        self.assertIsNotNone(terrain.fracterra_final)
        s.levels = 10  # not built: 1025^2 draws the size estimate, and "out of date"
        bad = set()
        for method in ("MIDPOINT", "ADDITIONS", "FBM", "SPECTRAL", "INTERPOLATED", "MANDELBROT"):
            for falloff, sea, source, preset in (("NONE", "NONE", "NONE", "NONE"), ("RADIAL", "HEIGHT", "IMAGE", "LAND"),
                                                 ("CUSTOM", "FRACTION", "DEM", "CUSTOM"),
                                                 ("SQUARE", "NONE", "OBJECT", "BADLANDS")):
                s.method, s.falloff, s.sea, s.reference_source, s.erode_preset = method, falloff, sea, source, preset
                for panel in (panels.FRACTERRA_PT_terrain, rivers.FRACTERRA_PT_rivers, panels.FRACTERRA_PT_measures):
                    bad |= set(self.too_long(self.texts(panel.draw, bpy.context)))
        self.assertEqual(bpy.ops.mesh.fracterra_planet_add(level=2), {"FINISHED"})
        bad |= set(self.too_long(self.texts(panels.FRACTERRA_PT_planet.draw, bpy.context)))
        for method in ("FPL3D", "FPL", "KOCH", "IFS", "PROFILE"):
            self.assertEqual(bpy.ops.curve.fracterra_polyline_add(method=method, depth=2, ifs_points=10), {"FINISHED"})
            bad |= set(self.too_long(self.texts(panels.FRACTERRA_PT_polyline.draw, bpy.context)))
        self.maxDiff = None
        self.assertEqual(sorted(bad), [])

    def test_the_jargon_is_in_the_tooltips(self):
        props = {p.name: p for p in mod("core").params.TERRAIN_OBJECT_PARAMS}
        planet = {p.name: p for p in mod("core").params.PLANET_OBJECT_PARAMS}
        self.assertEqual(props["splat_rules"].label, "Material Rules")
        self.assertIn("Splat", props["splat_rules"].description)
        self.assertEqual(props["levelling"].label, "Remove Tilt")
        self.assertIn("Levelling", props["levelling"].description)
        self.assertEqual(props["rivers_width_exponent"].label, "Width Growth")
        self.assertEqual(planet["frequency"].label, "Continents")
        self.assertEqual(planet["frequency"].unit_text, "")

    def test_a_large_radius_is_shown_in_km(self):
        clear_scene()
        self.assertEqual(bpy.ops.mesh.fracterra_planet_add(level=2), {"FINISHED"})
        s = bpy.context.active_object.fracterra_planet
        self.assertAlmostEqual(s.radius_km, 6371.0, places=3)
        s.radius_km = 3389.5  # Mars
        self.assertAlmostEqual(s.radius, 3389500.0, delta=0.5)
        log = self.texts(mod("blender.ui.panels").FRACTERRA_PT_planet.draw, bpy.context)
        self.assertIn("Radius (km)", [text for kind, text, _s, _e in log if kind == "label"])
        self.assertNotIn("radius", [e[1] for kind, _t, _s, e in log if kind == "prop"])


if __name__ == "__main__":
    addon_harness.run(globals())
