# SPDX-License-Identifier: GPL-3.0-or-later
"""Menu entries, each an operator referred to by its id string."""

import bpy


def menu_mesh_add(self, context):
    self.layout.operator("mesh.fracterra_terrain_add", text="Fractal Terrain", icon="RNDCURVE")
    self.layout.operator("mesh.fracterra_planet_add", text="Fractal Planet", icon="MESH_UVSPHERE")


def menu_curve_add(self, context):
    self.layout.operator("curve.fracterra_polyline_add", text="Fractal Polyline", icon="IPO_ELASTIC")
    self.layout.operator("curve.fracterra_coastline_add", text="Terrain Coastline", icon="MOD_OCEAN")


def menu_file_export(self, context):
    self.layout.operator("export_scene.fracterra_pov", text="POV-Ray (fracterra) (.pov)")
    self.layout.operator("export_scene.fracterra_heights", text="Terrain Heights (fracterra) (.tif/.exr/.raw)")
    self.layout.operator("export_scene.fracterra_tiles", text="Build Tile Set (fracterra) (folder)")


def menu_file_import(self, context):
    self.layout.operator("import_scene.fracterra_dem", text="DEM as Terrain (fracterra) (.tif/.hgt/.asc/...)")
    self.layout.operator("import_scene.fracterra_tiles", text="Tile Set (fracterra) (manifest.json)")


def menu_object(self, context):
    self.layout.operator("object.fracterra_fractalize", icon="MOD_DISPLACE")


# (menu, draw function) pairs, appended on register and removed on unregister.
MENUS = (
    (bpy.types.VIEW3D_MT_mesh_add, menu_mesh_add),
    (bpy.types.VIEW3D_MT_curve_add, menu_curve_add),
    (bpy.types.TOPBAR_MT_file_export, menu_file_export),
    (bpy.types.TOPBAR_MT_file_import, menu_file_import),
    (bpy.types.VIEW3D_MT_object, menu_object),
)
