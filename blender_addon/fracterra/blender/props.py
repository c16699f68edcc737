"""Blender properties made from the one parameter list (core.params)."""

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from ..core import params


def bpy_property(p, update=None):
    """The bpy.props definition of parameter `p` (update: optional callback)."""
    kw = {"name": p.label, "description": p.description, "default": p.default}
    if update is not None:
        kw["update"] = update
    if p.kind in ("int", "float"):
        for key in ("min", "max", "soft_min", "soft_max"):
            if getattr(p, key) is not None:
                kw[key] = getattr(p, key)
    if p.kind == "int":
        return IntProperty(**kw)
    if p.kind == "float":
        kw["subtype"], kw["unit"] = p.subtype, p.unit
        if p.precision is not None:
            kw["precision"] = p.precision
        return FloatProperty(**kw)
    if p.kind == "bool":
        return BoolProperty(**kw)
    if p.kind == "enum":
        kw["items"] = [(ident, label, tip, number) for ident, label, tip, number in p.items]
        return EnumProperty(**kw)
    if p.kind == "string":
        return StringProperty(**kw)
    raise TypeError(f"unknown parameter kind {p.kind!r} for {p.name}")


def terrain_annotations(update=None):
    """{name: property} for every terrain setting, for operators and the PropertyGroup."""
    return {p.name: bpy_property(p, update) for p in params.TERRAIN_PARAMS}


def _on_setting_changed(self, context):
    # Live editing from the sidebar: regenerate only when the user asked for it.
    if self.auto_update and self.is_terrain:
        from .terrain_build import regenerate_object  # late import: avoids a cycle
        obj = self.id_data
        try:
            regenerate_object(obj, context)
        except Exception as e:  # an update callback cannot report; show it in the panel
            self.last_error = str(e)
        else:
            self.last_error = ""


class FRACTERRA_PG_terrain(bpy.types.PropertyGroup):
    """The settings of a fractal terrain, kept on its object for re-editing."""


FRACTERRA_PG_terrain.__annotations__ = {
    "is_terrain": BoolProperty(name="Fractal Terrain", default=False,
                               description="This object was made by Add > Mesh > Fractal Terrain"),
    "auto_update": BoolProperty(name="Auto Update", default=False,
                                description="Regenerate the terrain whenever a setting changes"),
    "last_error": StringProperty(name="Last Error", default="", options={"SKIP_SAVE"}),
    **terrain_annotations(_on_setting_changed),
}


def copy_settings(src, dst):
    """Copies every terrain setting between operators and PropertyGroups."""
    for p in params.TERRAIN_PARAMS:
        setattr(dst, p.name, getattr(src, p.name))


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
    if method in params.DYADIC_METHODS:
        box = col.box().column(align=True)
        box.prop(data, "reference_source")
        if data.reference_source == "OBJECT":
            if show_reference_pickers:
                box.prop_search(data, "reference_object", bpy.data, "objects")
            box.prop(data, "reference_scale")
        elif data.reference_source == "IMAGE":
            if show_reference_pickers:
                box.prop_search(data, "reference_image", bpy.data, "images")
            box.prop(data, "reference_levels")
            box.prop(data, "reference_height")
            box.prop(data, "reference_scale")
    sub = col.column(heading="Mesh", align=True)
    sub.prop(data, "uvs")
    sub.prop(data, "smooth")
