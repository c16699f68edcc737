# SPDX-License-Identifier: GPL-3.0-or-later
"""In real Blender: the add-on's properties are the library's parameter
tables (fracterra/params.h). Every setting of ft_terrain_params is a property
of the Add Fractal Terrain operator and of the object's PropertyGroup, every
setting of ft_polyline_params one of Add Fractal Polyline and of its
PropertyGroup, and every setting of ft_fractalize_params one of Object >
Fractalize, with the library's label, default, range and enum items; where
Blender differs (a default, a narrower range) it says so once, with a
reason, in core/params.py."""

import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_harness  # noqa: E402

import bpy  # noqa: E402


def core():
    return addon_harness.submodule("core")


def rna_properties(kind="terrain"):
    if kind == "terrain":
        yield "operator", bpy.ops.mesh.fracterra_terrain_add.get_rna_type().properties
        yield "PropertyGroup", bpy.types.Object.bl_rna.properties["fracterra_terrain"].fixed_type.properties
    elif kind == "polyline":
        yield "operator", bpy.ops.curve.fracterra_polyline_add.get_rna_type().properties
        yield "PropertyGroup", bpy.types.Object.bl_rna.properties["fracterra_polyline"].fixed_type.properties
    elif kind == "fractalize":
        yield "operator", bpy.ops.object.fracterra_fractalize.get_rna_type().properties


# The structs whose settings are Blender properties, and how many (operator and
# PropertyGroup together) at least: a kind that lost its properties fails.
KINDS = {"terrain": 2 * 20 + 1, "polyline": 2 * 10, "fractalize": 8}


class TerrainPropertiesTest(unittest.TestCase):
    def setUp(self):
        self.params = core().params
        self.rows = core().library().param_rows["terrain"]

    def test_every_library_setting_is_a_property_with_its_label_default_and_range(self):
        for kind, least in KINDS.items():
            with self.subTest(kind=kind):
                self.assertGreaterEqual(self.check_kind(kind), least, kind)

    def check_kind(self, kind):
        rows = core().library().param_rows[kind]
        overrides = self.params.BLENDER_OVERRIDES.get(kind, {})
        limits = self.params.BLENDER_LIMITS.get(kind, {})
        skipped = self.params.NOT_PROPERTIES.get(kind, {})
        checked = 0
        for where, props in rna_properties(kind):
            where = f"{kind} {where}"
            for row in rows:
                name = row["name"]
                if (not row["settable"] or row["type"] in ("pointer", "callback", "string") or name in skipped
                        or row["count"] != 1):
                    self.assertNotIn(name, props.keys(), f"{where}: {name} is not a setting")
                    continue
                checked += 1
                prop = props[name]
                self.assertEqual(prop.name, row["label"], (where, name))
                if row["type"] == "enum":
                    items = [(i.identifier, i.value) for i in prop.enum_items]
                    self.assertEqual(items, [(i["name"], i["value"]) for i in row["items"]], (where, name))
                    if name in overrides:  # the add-on's own default, with its reason
                        self.assertEqual(prop.default, overrides[name][0], (where, name))
                        continue
                    default = next(i["value"] for i in row["items"] if i["name"] == prop.default)
                    want = overrides.get(name, (None,))[0]
                    if want is not None:
                        self.assertEqual(prop.default, want, (where, name))
                    else:
                        self.assertEqual(default, row["default"], (where, name))
                    continue
                want = overrides.get(name, (row["default"],))[0]
                if row["type"] == "bool":
                    self.assertEqual(prop.default, bool(want), (where, name))
                    continue
                self.assertAlmostEqual(prop.default, want, places=5, msg=(where, name))
                lo, hi = limits.get(name, (row["hard_min"], row["hard_max"], ""))[:2]
                lo, hi = -1e300 if lo is None else lo, 1e300 if hi is None else hi  # None: unbounded
                # Blender's properties have no open bounds: an excluded bound moves in by 1e-6.
                if row["min_exclusive"]:
                    self.assertGreater(prop.hard_min, lo, (where, name))
                    self.assertLess(prop.hard_min, lo + 1e-5 * max(1, abs(lo)), (where, name))
                elif abs(lo) < 1e30:
                    self.assertAlmostEqual(prop.hard_min, max(lo, -2**31), places=4, msg=(where, name))
                if row["max_exclusive"]:
                    self.assertLess(prop.hard_max, hi, (where, name))
                    self.assertGreater(prop.hard_max, hi - 1e-5 * max(1, abs(hi)), (where, name))
                elif abs(hi) < 1e30:
                    self.assertAlmostEqual(prop.hard_max, min(hi, 2**31 - 1), delta=abs(hi) * 1e-6,
                                           msg=(where, name))
        return checked

    def test_blender_offers_no_levels_it_cannot_hold(self):
        """levels 13 is 8193^2 vertices, 2^28 face corners: more than a Blender mesh array holds
        (width x height is refused before any work instead: test_addon.py)."""
        too_large = addon_harness.submodule("core.mesh_limits").too_large
        for where, props in rna_properties():
            side = 2 ** props["levels"].hard_max + 1
            self.assertIsNone(too_large(side, side), where)
            self.assertIsNotNone(too_large(2 * side - 1, 2 * side - 1), where)

    def test_overrides_and_limits_each_give_a_reason(self):
        for table in (self.params.BLENDER_OVERRIDES, self.params.BLENDER_LIMITS, self.params.NOT_PROPERTIES):
            for kind, entries in table.items():
                for name, entry in entries.items():
                    reason = entry if isinstance(entry, str) else entry[-1]
                    self.assertGreater(len(reason), 30, (kind, name))

    def test_which_fields_each_method_shows_comes_from_the_library(self):
        for kind, params in (("terrain", self.params.TERRAIN_PARAMS), ("polyline", self.params.POLYLINE_PARAMS)):
            rows = core().library().param_rows[kind]
            by_name = {p.name: p for p in params}
            methods = {i["value"]: i["name"] for i in next(r for r in rows if r["name"] == "method")["items"]}
            for row in rows:
                if row["name"] in by_name and row["methods"] != 2**64 - 1:
                    shown = {methods[v] for v in methods if row["methods"] >> v & 1}
                    self.assertEqual(set(by_name[row["name"]].methods), shown, (kind, row["name"]))


if __name__ == "__main__":
    addon_harness.run(globals())
