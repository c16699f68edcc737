# SPDX-License-Identifier: GPL-3.0-or-later
"""A Final kept beside its Preview. Auto Update edits a terrain (or planet) at
its Preview level; when the object holds its Final, the first such edit keeps
that Final's mesh on the object (Object.fracterra_final) and that of each of
its water objects (WATER_FINAL, a custom property) and shows the Preview in
its place. The Final stays until the artist builds a new one (Build Final
rewrites the kept mesh in place and swaps it back) or goes back to it (Back to
Final: its mesh, its water and its settings). Undo restores the pointers with
the meshes, so the sidebar and the scene agree after Ctrl+Z too.
"""

import bpy

from .water import water_objects

# On a water object: its data at the kept Final.
WATER_FINAL = "fracterra_final_data"


def kept(obj):
    """The kept Final mesh of terrain or planet `obj`, or None."""
    return getattr(obj, "fracterra_final", None)


def keep(obj):
    """Keeps the mesh `obj` holds now (its Final) and its water's data."""
    obj.fracterra_final = obj.data
    for child in water_objects(obj):
        child[WATER_FINAL] = child.data


def _remove_if_unused(data):
    if data is not None and data.users == 0:
        (bpy.data.meshes if isinstance(data, bpy.types.Mesh) else bpy.data.curves).remove(data)


def _swap(obj, data):
    """Gives `obj` the data `data` (with the materials of what it held); the old
    data goes when nothing else uses it."""
    old = obj.data
    if old is data:
        return
    if len(old.materials):
        data.materials.clear()
        for material in old.materials:
            data.materials.append(material)
    obj.data = data
    _remove_if_unused(old)


def _forget_water(obj, restore):
    for child in water_objects(obj):
        data = child.get(WATER_FINAL)
        if data is None:
            continue
        del child[WATER_FINAL]
        if restore:
            _swap(child, data)
        else:
            _remove_if_unused(data)


def bring_back(obj, water=False):
    """Puts the kept Final (rewritten or not) back as `obj`'s mesh; the Preview
    goes. `water`: the water objects get their kept data back too (Back to
    Final); else theirs is let go (a new Final built its own)."""
    final = obj.fracterra_final
    obj.fracterra_final = None
    _swap(obj, final)
    _forget_water(obj, water)


def drop(obj):
    """Lets the kept Final go (a Final of another grid was built instead)."""
    final = kept(obj)
    if final is None:
        return
    obj.fracterra_final = None
    _remove_if_unused(final)
    _forget_water(obj, False)


def register():
    bpy.types.Object.fracterra_final = bpy.props.PointerProperty(
        type=bpy.types.Mesh, name="Kept Final",
        description="The Final mesh kept while Auto Update edits the Preview (Build Final rebuilds it, Back to "
                    "Final shows it again)")


def unregister():
    del bpy.types.Object.fracterra_final
