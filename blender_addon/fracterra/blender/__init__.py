# SPDX-License-Identifier: GPL-3.0-or-later
"""The Blender side of the add-on, one folder per role (imports point upwards:
each folder imports only the folders above it; tests/python/test_addon_layers.py checks it):
    common/  leaves: reporting, jobs (progress bar, Esc), preferences, images, widgets, presets
    build/   Blender data from and to library arrays: mesh, curve, terrain, planet, polyline, erosion, objects
    ui/      properties and PropertyGroups, how settings are laid out, panels, menus
    ops/     operators (panels and menus name them by their id strings, never import them)
This file only lists the classes and registers them.
"""

import bpy

from .ops import dem_io as dem_io_ops
from .ops import fractalize as fractalize_op
from .ops import measure as measure_op
from .ui import panels
from .ui import rivers_panel
from .ops import rivers as rivers_ops
from .ops import polyline as polyline_ops
from .ops import pov_export
from .common import preferences as prefs
from .common import presets
from .ui import properties as props
from .ui import erosion_layout
from .ops import terrain as terrain_ops
from .ops import planet as planet_ops
from .ops import tiles_build as tiles_build_op
from .ops import tiles_import as tiles_import_op
from .ui.menus import MENUS
from .build import kept_final
from .build.children import VISIBILITY_POLL, follow_visibility, poll_visibility
from .build.objects import restore_after_undo
from .build.terrain import final_for_render

classes = (
    props.FRACTERRA_PG_terrain,
    props.FRACTERRA_PG_measures,
    props.FRACTERRA_PG_polyline,
    props.FRACTERRA_PG_planet,
    terrain_ops.FRACTERRA_OT_terrain_add,
    terrain_ops.FRACTERRA_OT_terrain_regenerate,
    terrain_ops.FRACTERRA_OT_back_to_final,
    terrain_ops.FRACTERRA_OT_reference_image_open,
    planet_ops.FRACTERRA_OT_planet_add,
    planet_ops.FRACTERRA_OT_planet_regenerate,
    polyline_ops.FRACTERRA_OT_polyline_add,
    polyline_ops.FRACTERRA_OT_polyline_regenerate,
    polyline_ops.FRACTERRA_OT_coastline_add,
    rivers_ops.FRACTERRA_OT_rivers,
    measure_op.FRACTERRA_OT_measure,
    pov_export.FRACTERRA_OT_export_pov,
    fractalize_op.FRACTERRA_OT_fractalize,
    dem_io_ops.FRACTERRA_OT_import_dem,
    dem_io_ops.FRACTERRA_OT_export_heights,
    tiles_import_op.FRACTERRA_OT_import_tiles,
    tiles_build_op.FRACTERRA_OT_export_tiles,
    panels.FRACTERRA_PT_terrain,
    rivers_panel.FRACTERRA_PT_rivers,
    panels.FRACTERRA_PT_planet,
    panels.FRACTERRA_PT_polyline,
    panels.FRACTERRA_PT_measures,
    prefs.FracterraPreferences,
)

def on_register():
    for handlers in (bpy.app.handlers.undo_post, bpy.app.handlers.redo_post):
        handlers.append(restore_after_undo)
    bpy.app.handlers.render_pre.append(final_for_render)
    bpy.app.handlers.depsgraph_update_post.append(follow_visibility)
    bpy.app.timers.register(poll_visibility, first_interval=VISIBILITY_POLL, persistent=True)
    kept_final.register()
    bpy.types.Object.fracterra_terrain = bpy.props.PointerProperty(type=props.FRACTERRA_PG_terrain)
    bpy.types.Object.fracterra_measures = bpy.props.PointerProperty(type=props.FRACTERRA_PG_measures)
    bpy.types.Object.fracterra_polyline = bpy.props.PointerProperty(type=props.FRACTERRA_PG_polyline)
    bpy.types.Object.fracterra_planet = bpy.props.PointerProperty(type=props.FRACTERRA_PG_planet)
    erosion_layout.register()
    try:
        presets.install_presets()
    except OSError as e:  # a read-only user folder must not stop the add-on
        print(f"fracterra: presets not installed: {e}")


def on_unregister():
    for handlers in (bpy.app.handlers.undo_post, bpy.app.handlers.redo_post):
        if restore_after_undo in handlers:
            handlers.remove(restore_after_undo)
    if final_for_render in bpy.app.handlers.render_pre:
        bpy.app.handlers.render_pre.remove(final_for_render)
    if follow_visibility in bpy.app.handlers.depsgraph_update_post:
        bpy.app.handlers.depsgraph_update_post.remove(follow_visibility)
    if bpy.app.timers.is_registered(poll_visibility):
        bpy.app.timers.unregister(poll_visibility)
    kept_final.unregister()
    erosion_layout.unregister()
    del bpy.types.Object.fracterra_planet
    del bpy.types.Object.fracterra_polyline
    del bpy.types.Object.fracterra_measures
    del bpy.types.Object.fracterra_terrain
