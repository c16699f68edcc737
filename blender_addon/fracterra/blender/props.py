"""Blender properties made from the one parameter list (core.params)."""

import bpy
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, FloatVectorProperty, IntProperty,
                       StringProperty)

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
    if p.kind == "vector":
        return FloatVectorProperty(size=3, subtype=p.subtype, unit=p.unit, **kw)
    raise TypeError(f"unknown parameter kind {p.kind!r} for {p.name}")


def terrain_annotations(update=None, param_list=None):
    """{name: property} for every setting (terrain unless another list is given)."""
    return {p.name: bpy_property(p, update) for p in param_list or params.TERRAIN_PARAMS}


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


class FRACTERRA_PG_measures(bpy.types.PropertyGroup):
    """Measures of an object, filled by object.fracterra_measure (the panel only shows them)."""
    kind: StringProperty(name="Measured", default="", description="What was measured: terrain or polylines")
    hurst: FloatProperty(name="H", description="Hurst exponent, by the library's recommended estimator for the "
                                               "grid (the one `fracterra analyze` reports)")
    estimator: StringProperty(name="Estimator", default="", description="The Hurst estimator used")
    estimator_reason: StringProperty(name="Why", default="", description="Why the estimator was chosen")
    dimension: FloatProperty(name="D", description="Fractal dimension (terrain: 3 - H; polylines: box counting)")
    stderr: FloatProperty(name="Std Error", description="Standard error of the fitted slope")
    eta: FloatProperty(name="eta", description="Max deviation of the main line from its chord / chord length")
    chi: FloatProperty(name="chi", description="Mean deviation from the chord / chord length")
    gamma: FloatProperty(name="gamma", description="Line length / chord length (elongation)")
