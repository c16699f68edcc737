# SPDX-License-Identifier: GPL-3.0-or-later
"""fracterra: fractal terrains for Blender on the native libfracterra core.

A thin entry point: the bpy-free binding lives in `core/`, the operators,
panels and properties in `blender/`. Without Blender (pytest) only `core` is
imported.
"""

bl_info = {
    "name": "Fracterra",
    "author": "fracterra authors",
    "version": (0, 6, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Add > Mesh > Fractal Terrain; Sidebar > Fracterra",
    "description": "Fractal terrains (midpoint displacement, successive additions, fBm, spectral) "
                   "on a fast native core, re-editable in place",
    "category": "Add Mesh",
}

try:
    import bpy  # noqa: F401
except ImportError:  # outside Blender: only fracterra.core is usable
    bpy = None

if bpy is not None:
    from .blender import MENUS as menus, classes, on_register, on_unregister

    def register():
        for cls in classes:
            bpy.utils.register_class(cls)
        on_register()
        for menu, draw in menus:
            menu.append(draw)

    def unregister():
        for menu, draw in reversed(menus):
            menu.remove(draw)
        on_unregister()
        for cls in reversed(classes):
            bpy.utils.unregister_class(cls)
