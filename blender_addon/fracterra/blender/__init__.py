"""The Blender side of the add-on: properties, operators, panels, menus."""

import bpy

from . import fractalize_op, panels, polyline_ops, pov_export, presets, props, terrain_ops

classes = (
    props.FRACTERRA_PG_terrain,
    props.FRACTERRA_PG_measures,
    terrain_ops.FRACTERRA_OT_terrain_add,
    terrain_ops.FRACTERRA_OT_terrain_regenerate,
    polyline_ops.FRACTERRA_OT_polyline_add,
    polyline_ops.FRACTERRA_OT_coastline_add,
    polyline_ops.FRACTERRA_OT_measure,
    pov_export.FRACTERRA_OT_export_pov,
    fractalize_op.FRACTERRA_OT_fractalize,
    panels.FRACTERRA_PT_terrain,
    polyline_ops.FRACTERRA_PT_measures,
    panels.FracterraPreferences,
)

menus = (
    (bpy.types.VIEW3D_MT_mesh_add, terrain_ops.menu_mesh_add),
    (bpy.types.VIEW3D_MT_curve_add, polyline_ops.menu_curve_add),
    (bpy.types.TOPBAR_MT_file_export, pov_export.menu_export),
    (bpy.types.VIEW3D_MT_object, fractalize_op.menu_object),
)


def on_register():
    bpy.types.Object.fracterra_terrain = bpy.props.PointerProperty(type=props.FRACTERRA_PG_terrain)
    bpy.types.Object.fracterra_measures = bpy.props.PointerProperty(type=props.FRACTERRA_PG_measures)
    try:
        presets.install_presets()
    except OSError as e:  # a read-only user folder must not stop the add-on
        print(f"fracterra: presets not installed: {e}")


def on_unregister():
    del bpy.types.Object.fracterra_measures
    del bpy.types.Object.fracterra_terrain
