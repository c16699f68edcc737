"""How the settings are laid out: grouped, showing only what the chosen method
uses. Shared by the operators' redo panels and the sidebar (reads only
core.params, so panels and operators both import it without a circle)."""

import bpy

from ..core import params
from . import erosion_ui


def draw_settings(layout, data, show_reference_pickers=True):
    """Lays out the settings of `data` (operator or PropertyGroup), grouped, showing
    only what the chosen method uses."""
    method = data.method
    col = layout.column(align=False)
    col.use_property_split = True
    col.use_property_decorate = False
    col.prop(data, "method")
    sub = col.column(align=True)
    if method in params.DYADIC_METHODS:
        sub.prop(data, "levels")
        side = 2 ** data.levels + 1
        sub.label(text=f"{side} x {side} vertices", icon="MESH_GRID")
    else:
        sub.prop(data, "width")
        sub.prop(data, "height")
    sub = col.column(align=True)
    for name in ("hurst", "sigma", "seed", "periodic"):
        if params.is_used(params.PARAMS_BY_NAME[name], method):
            sub.prop(data, name)
    sub = col.column(align=True)
    sub.prop(data, "world_size")
    row = sub.row(heading="Sea Level", align=True)
    row.prop(data, "use_sea_level", text="")
    r = row.row(align=True)
    r.active = data.use_sea_level
    r.prop(data, "sea_level", text="")
    if method == "FBM":
        box = col.box().column(align=True)
        box.label(text="Noise")
        for name in ("basis", "variant", "octaves", "lacunarity", "gain", "frequency", "offset",
                     "octave_rotation", "warp"):
            box.prop(data, name)
    elif method == "INTERPOLATED":
        col.prop(data, "lacunarity")
    elif method == "MANDELBROT":
        box = col.box().column(align=True)
        box.label(text="Mandelbrot Set")
        for name in ("center_x", "center_y", "zoom", "iterations", "supersample"):
            box.prop(data, name)
    if method in params.DYADIC_METHODS:
        box = col.box().column(align=True)
        box.prop(data, "reference_source")
        if data.reference_source == "OBJECT":
            if show_reference_pickers:
                box.prop_search(data, "reference_object", bpy.data, "objects")
            box.prop(data, "reference_scale")
        elif data.reference_source == "IMAGE":
            if show_reference_pickers:
                row = box.row(align=True)
                row.prop_search(data, "reference_image", bpy.data, "images")
                if isinstance(data, bpy.types.PropertyGroup):  # the sidebar: open a file for this terrain
                    row.operator("object.fracterra_reference_image_open", text="", icon="FILEBROWSER")
            box.prop(data, "reference_levels")
            box.prop(data, "reference_height")
            box.prop(data, "reference_scale")
        elif data.reference_source == "DEM":
            box.prop(data, "reference_file")
            box.prop(data, "reference_levels")
            box.prop(data, "reference_height", text="Relief if not georeferenced")
            box.prop(data, "reference_scale")
    erosion_ui.draw_erosion(col, data)
    sub = col.column(heading="Mesh", align=True)
    sub.prop(data, "uvs")
    sub.prop(data, "smooth")


def draw_polyline_settings(layout, data):
    col = layout.column()
    col.use_property_split = True
    col.use_property_decorate = False
    method = data.method
    for p in params.POLYLINE_PARAMS:
        if p.name in ("start", "end") and data.base_source != "POINTS":
            continue
        if params.is_used(p, method):
            col.prop(data, p.name)
