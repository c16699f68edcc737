"""The Blender side of the add-on: properties, operators, panels, menus.

Modules import only downwards, never in a circle:
    reporting, widgets, prefs, mesh_build, curve_build   (leaves: core and bpy only)
    <- progress (long jobs: worker thread, status bar, Esc; imports reporting)
    <- terrain_build, polyline_build, terrain_objects, settings_ui
    <- props (PropertyGroups; auto-update calls terrain_build)
    <- terrain_ops, polyline_ops, measure_op, fractalize_op, pov_export, dem_io_ops,
       tiles_import_op (operators)
    <- panels, menus (refer to operators by their id strings)
tests/python/test_addon_layers.py checks this order.
"""

import bpy

from . import (dem_io_ops, fractalize_op, measure_op, panels, polyline_ops, pov_export, prefs, presets, props,
               terrain_ops, tiles_import_op)
from .menus import MENUS

classes = (
    props.FRACTERRA_PG_terrain,
    props.FRACTERRA_PG_measures,
    props.FRACTERRA_PG_polyline,
    terrain_ops.FRACTERRA_OT_terrain_add,
    terrain_ops.FRACTERRA_OT_terrain_regenerate,
    terrain_ops.FRACTERRA_OT_reference_image_open,
    polyline_ops.FRACTERRA_OT_polyline_add,
    polyline_ops.FRACTERRA_OT_polyline_regenerate,
    polyline_ops.FRACTERRA_OT_coastline_add,
    measure_op.FRACTERRA_OT_measure,
    pov_export.FRACTERRA_OT_export_pov,
    fractalize_op.FRACTERRA_OT_fractalize,
    dem_io_ops.FRACTERRA_OT_import_dem,
    dem_io_ops.FRACTERRA_OT_export_heights,
    tiles_import_op.FRACTERRA_OT_import_tiles,
    panels.FRACTERRA_PT_terrain,
    panels.FRACTERRA_PT_polyline,
    panels.FRACTERRA_PT_measures,
    prefs.FracterraPreferences,
)

def on_register():
    bpy.types.Object.fracterra_terrain = bpy.props.PointerProperty(type=props.FRACTERRA_PG_terrain)
    bpy.types.Object.fracterra_measures = bpy.props.PointerProperty(type=props.FRACTERRA_PG_measures)
    bpy.types.Object.fracterra_polyline = bpy.props.PointerProperty(type=props.FRACTERRA_PG_polyline)
    try:
        presets.install_presets()
    except OSError as e:  # a read-only user folder must not stop the add-on
        print(f"fracterra: presets not installed: {e}")


def on_unregister():
    del bpy.types.Object.fracterra_polyline
    del bpy.types.Object.fracterra_measures
    del bpy.types.Object.fracterra_terrain
