"""The Blender side of the add-on: properties, operators, panels, menus."""

import bpy

from . import panels, presets, props, terrain_ops

classes = (
    props.FRACTERRA_PG_terrain,
    terrain_ops.FRACTERRA_OT_terrain_add,
    terrain_ops.FRACTERRA_OT_terrain_regenerate,
    panels.FRACTERRA_PT_terrain,
    panels.FracterraPreferences,
)

menus = (
    (bpy.types.VIEW3D_MT_mesh_add, terrain_ops.menu_mesh_add),
)


def on_register():
    bpy.types.Object.fracterra_terrain = bpy.props.PointerProperty(type=props.FRACTERRA_PG_terrain)
    try:
        presets.install_presets()
    except OSError as e:  # a read-only user folder must not stop the add-on
        print(f"fracterra: presets not installed: {e}")


def on_unregister():
    del bpy.types.Object.fracterra_terrain
