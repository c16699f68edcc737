# SPDX-License-Identifier: GPL-3.0-or-later
"""How the settings are laid out: grouped, showing only what the chosen method
uses. Shared by the operators' redo panels and the sidebar (reads only
core.params, so panels and operators both import it without a circle)."""

import bpy

from ...core import params
from . import erosion_layout
from ..common.widgets import draw_setting


# The characters of an enum's label that its 40 % of the sidebar row shows whole.
ENUM_LABEL_CHARACTERS = 12


def setting_prop(layout, data, name, p=None):
    """layout.prop, except that without the property split (the narrow sidebar)
    an enum gets its label beside it (Blender would drop it) and a file path
    its label above it. `p`: the setting's
    Param (a terrain's, by its name, unless given)."""
    # An operator's own RNA lacks the properties given by __annotations__ after
    # its class body (they are its OperatorProperties'): the redo panel raised here.
    rna = data.properties.bl_rna if isinstance(data, bpy.types.Operator) else data.bl_rna
    prop = rna.properties[name]
    if not layout.use_property_split and prop.type == "STRING" and prop.subtype == "FILE_PATH":
        # A path beside its label leaves room for neither: the label above it.
        col = layout.column(align=True)
        col.label(text=prop.name)
        col.prop(data, name, text="")
        return
    if layout.use_property_split or prop.type != "ENUM":
        draw_setting(layout, data, name, p if p is not None else params.PARAMS_BY_NAME.get(name))
        return
    if len(prop.name) > ENUM_LABEL_CHARACTERS:  # beside its menu it would be cut: above it
        col = layout.column(align=True)
        col.label(text=prop.name)
        col.prop(data, name, text="")
        return
    row = layout.split(factor=0.4, align=True)
    row.label(text=prop.name)
    row.prop(data, name, text="")


# Drawn above for every method that uses them (or by draw_landform and the reference box).
_SHARED = {"method", "levels", "width", "height", "hurst", "sigma", "seed", "periodic", "world_size",
           "reference_scale"}


_prop = setting_prop


def _own_settings(method):
    """The library's terrain settings that `method` uses and only some methods do,
    beyond the shared ones drawn above, in the table's order."""
    return [p.name for p in params.TERRAIN_PARAMS
            if p.field and p.methods is not None and method in p.methods and p.name not in _SHARED]


def draw_settings(layout, data, show_reference_pickers=True, compact=False):
    """Lays out the settings of `data` (operator or PropertyGroup), grouped, showing
    only what the chosen method uses. `compact` (the sidebar): labels inside the
    fields, where the split layout of the redo panel would cut them."""
    method = data.method
    col = layout.column(align=False)
    col.use_property_split = not compact
    col.use_property_decorate = False
    _prop(col, data, "method")
    sub = col.column(align=True)
    if method in params.DYADIC_METHODS:
        _prop(sub, data, "levels")
        side = 2 ** data.levels + 1
        sub.label(text=f"Final grid: {side} x {side}", icon="MESH_GRID")
        _prop(sub, data, "preview_levels")
    else:
        _prop(sub, data, "width")
        _prop(sub, data, "height")
    sub = col.column(align=True)
    for name in ("hurst", "sigma", "seed", "periodic"):
        if params.is_used(params.PARAMS_BY_NAME[name], method):
            _prop(sub, data, name)
    sub = col.column(align=True)
    _prop(sub, data, "world_size")
    draw_landform(col, data, show_reference_pickers)
    own = _own_settings(method)
    if own:
        # The method's own settings, in a box under its name: which they are is the
        # library's table (each field's methods), so a new method needs no case here.
        box = col.box().column(align=True)
        box.label(text=next(label for ident, label, _doc, _v in params.PARAMS_BY_NAME["method"].items
                            if ident == method))
        for name in own:
            _prop(box, data, name)
    if method in params.DYADIC_METHODS:
        box = col.box().column(align=True)
        _prop(box, data, "reference_source")
        if data.reference_source == "OBJECT":
            if show_reference_pickers:
                box.prop_search(data, "reference_object", bpy.data, "objects")
            _prop(box, data, "reference_scale")
        elif data.reference_source == "IMAGE":
            if show_reference_pickers:
                row = box.row(align=True)
                _prop(row, data, "reference_image_pick")  # readable images only (props.reference_image_picker)
                if isinstance(data, bpy.types.PropertyGroup):  # the sidebar: open a file for this terrain
                    row.operator("object.fracterra_reference_image_open", text="", icon="FILEBROWSER")
            _prop(box, data, "reference_levels")
            _prop(box, data, "reference_height")
            _prop(box, data, "reference_scale")
        elif data.reference_source == "DEM":
            _prop(box, data, "reference_file")
            _prop(box, data, "reference_levels")
            relief = box.column(align=True)
            relief.label(text="Relief if not georeferenced")
            relief.prop(data, "reference_height", text="")
            _prop(box, data, "reference_scale")
    erosion_layout.draw_erosion(col, data)
    _prop(col.column(align=True), data, "splat_rules")
    sub = col.column(heading="Mesh", align=True)
    _prop(sub, data, "uvs")
    _prop(sub, data, "smooth")


def draw_landform(col, data, show_pickers=True):
    """Levelling, offset, edge falloff and sea (the library's landform fields):
    the falloff's and the sea's own fields only when they are on; a custom
    falloff's mask source (an object, or an image with Open in the sidebar)."""
    box = col.box().column(align=True)
    box.label(text="Landform")
    _prop(box, data, "levelling")
    _prop(box, data, "height_offset")
    _prop(box, data, "falloff")
    falloff = data.falloff
    if falloff == "CUSTOM":
        _prop(box, data, "falloff_mask_source")
        if data.falloff_mask_source == "OBJECT":
            if show_pickers:
                box.prop_search(data, "falloff_mask_object", bpy.data, "objects", text="Object")
            _prop(box, data, "falloff_mask_soft")
        elif show_pickers:
            row = box.row(align=True)
            _prop(row, data, "falloff_mask_image_pick")  # readable images only (props.image_picker)
            if isinstance(data, bpy.types.PropertyGroup):  # the sidebar: open a file for this terrain
                op = row.operator("object.fracterra_reference_image_open", text="", icon="FILEBROWSER")
                op.target = "FALLOFF_MASK"
    # The width shapes the square and radial falloffs, and a custom one's soft outline.
    if falloff in ("SQUARE", "RADIAL") or (falloff == "CUSTOM" and data.falloff_mask_source == "OBJECT"
                                           and data.falloff_mask_soft):
        _prop(box, data, "falloff_width")
    if falloff != "NONE":
        _prop(box, data, "edge_level")
    _prop(box, data, "sea")
    if data.sea == "HEIGHT":
        _prop(box, data, "sea_level")
    elif data.sea == "FRACTION":
        _prop(box, data, "sea_fraction")


def draw_polyline_settings(layout, data, compact=False):
    col = layout.column()
    col.use_property_split = not compact
    col.use_property_decorate = False
    method = data.method
    for p in params.POLYLINE_PARAMS:
        if p.name in ("start", "end") and data.base_source != "POINTS":
            continue
        if params.is_used(p, method):
            _prop(col, data, p.name)
