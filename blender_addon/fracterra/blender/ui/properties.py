# SPDX-License-Identifier: GPL-3.0-or-later
"""Blender properties made from the one parameter list (core.params), and the
PropertyGroups kept on objects (terrain and polyline settings, measures)."""

import math

import bpy
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, FloatVectorProperty, IntProperty,
                       StringProperty)

from ...core import params
from . import erosion_layout
from ..build.polyline import regenerate_polyline
from ..build.objects import restore_settings, restoring
from ..build.terrain import preview_regenerate
from ..build import planet as planet_build
from ..common.widgets import km_name, shows_km


def bpy_property(p, update=None, options=None):
    """The bpy.props definition of parameter `p` (update: optional callback;
    options: e.g. {"SKIP_SAVE"})."""
    kw = {"name": p.label, "description": p.description, "default": p.default}
    if update is not None:
        kw["update"] = update
    if options is not None:
        kw["options"] = options
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
        if p.subtype != "NONE":
            kw["subtype"] = p.subtype
        return StringProperty(**kw)
    if p.kind == "vector":
        return FloatVectorProperty(size=3, subtype=p.subtype, unit=p.unit, **kw)
    raise TypeError(f"unknown parameter kind {p.kind!r} for {p.name}")


def display_property(p):
    """The setting `p` as Blender draws it when its values are too small for
    Blender's 6 decimals (params.display_scale_of): its value times
    p.display_scale, read from and written to the setting itself, so the
    setting (what presets, the library and the file keep) has one value."""
    scale = p.display_scale
    power = round(math.log10(scale))

    def get(self):
        return getattr(self, p.name) * scale

    def set(self, value):
        setattr(self, p.name, value / scale)

    kw = {key: getattr(p, key) * scale for key in ("min", "max", "soft_min", "soft_max") if getattr(p, key) is not None}
    return FloatProperty(name=f"{p.label} \u00d71e-{power}", get=get, set=set, precision=3, options={"SKIP_SAVE"},
                         description=f"{p.description}. Shown times 1e{power}: {p.default * scale:g} here is "
                                     f"{p.default:g}", **kw)


def km_property(p):
    """Setting `p` (in metres) as Blender draws it in km, read from and written
    to the setting itself, as display_property does."""
    def get(self):
        return getattr(self, p.name) / 1000.0

    def set(self, value):
        setattr(self, p.name, value * 1000.0)

    kw = {key: getattr(p, key) / 1000.0 for key in ("min", "max", "soft_min", "soft_max") if getattr(p, key) is not None}
    return FloatProperty(name=f"{p.label} (km)", get=get, set=set, precision=1, options={"SKIP_SAVE"},
                         description=f"{p.description}. Shown in km: {p.default / 1000:g} here is {p.default:g} m",
                         **kw)


def reference_image_choices(images):
    """The images a reference can be read from: files and generated images. Render
    Result and Viewer Node are left out: they hold no pixels that Python can read."""
    return [image.name for image in images if image.type not in ("RENDER_RESULT", "COMPOSITING")]


# Blender keeps only pointers to the strings of a dynamic enum's items: the
# list must outlive the callback (a known crash otherwise); one per picker.
_IMAGE_ITEMS = {}


def image_picker(store, description, item_tip, update=None):
    """The picker drawn for the image-name setting `store`: an enum over the
    readable images that reads and writes the stored name (prop_search would
    list every image, Render Result and Viewer Node included)."""
    items = _IMAGE_ITEMS.setdefault(store, [])

    def get_items(self, context):
        items[:] = [("NONE", "None", "No image", "BLANK1", 0)] + [
            (name, name, item_tip, "IMAGE_DATA", k + 1) for k, name in enumerate(reference_image_choices(bpy.data.images))]
        return items

    def get(self):
        names = reference_image_choices(bpy.data.images)
        name = getattr(self, store)
        return names.index(name) + 1 if name in names else 0

    def set(self, value):
        names = reference_image_choices(bpy.data.images)
        setattr(self, store, names[value - 1] if 0 < value <= len(names) else "")

    kw = {"update": update} if update is not None else {}
    return EnumProperty(name="Image", description=description, items=get_items, get=get, set=set,
                        options={"SKIP_SAVE"}, **kw)


def reference_image_picker(update=None):
    return image_picker("reference_image", "Image whose brightness gives the reference heights (files and "
                                           "generated images; Open loads a file)",
                        "Use this image's brightness as the reference heights", update)


def falloff_mask_image_picker(update=None):
    return image_picker("falloff_mask_image", "Image whose brightness is the falloff mask: white keeps the height, "
                                              "black gives the Edge Level (Open loads a file)",
                        "Use this image as the falloff mask", update)


def map_image_picker(what, update=None):
    """The image picker of the erosion mask or the rain map (`what`: the setting's prefix)."""
    role = "erosion acts" if what == "erosion_mask" else "rain falls"
    return image_picker(f"{what}_image", f"Image whose brightness says where {role}: white fully, black not at all "
                                         "(Open loads a file)", f"Use this image for where {role}", update)


def terrain_annotations(update=None, param_list=None, options=None):
    """{name: property} for every setting (terrain unless another list is given).
    A setting an erosion preset sets makes the preset Custom when changed by hand."""
    out = {}
    for p in param_list or params.TERRAIN_OBJECT_PARAMS:
        own = erosion_layout.leaves_preset(update) if p.name in erosion_layout.SET_BY_PRESET else update
        out[p.name] = bpy_property(p, own, options)
        if p.display_scale is not None:
            out[params.shown_name(p.name)] = display_property(p)
        if shows_km(p):
            out[km_name(p.name)] = km_property(p)
    if "reference_image" in out:
        out["reference_image_pick"] = reference_image_picker(update)
    if "falloff_mask_image" in out:
        out["falloff_mask_image_pick"] = falloff_mask_image_picker(update)
    for what in ("erosion_mask", "rain_map"):
        if what + "_image" in out:
            out[what + "_image_pick"] = map_image_picker(what, update)
    return out


def live_update(flag, regenerate, restore=None):
    """The update callback of a PropertyGroup's settings: with Auto Update on and
    the object made by the add-on (`flag`: is_terrain, is_polyline), regenerate
    its object (live editing from the sidebar, only when the user asked for it).
    On a failure `restore(obj)` puts back the settings of what is there."""
    def on_change(self, context):
        if self.auto_update and getattr(self, flag) and not restoring():
            try:
                regenerate(self.id_data, context)
            except Exception as e:  # an update callback cannot report; show it in the panel
                if restore is not None:
                    restore(self.id_data)
                self.last_error = str(e)
            else:
                self.last_error = ""
    return on_change


_on_setting_changed = live_update("is_terrain", preview_regenerate, restore_settings)


class FRACTERRA_PG_terrain(bpy.types.PropertyGroup):
    """The settings of a fractal terrain, kept on its object for re-editing."""


def editable_annotations(noun):
    """The flag, Auto Update and Last Error of an object the add-on made and
    rebuilds at its Preview level (terrain, planet): {name: property}."""
    return {
        f"is_{noun}": BoolProperty(name=f"Fractal {noun.title()}", default=False,
                                   description=f"This object was made by Add > Mesh > Fractal {noun.title()}"),
        "auto_update": BoolProperty(name="Auto Update", default=False,
                                    description=f"Regenerate the {noun} at its Preview level whenever a setting "
                                                "changes (Regenerate builds the Final level)"),
        "last_error": StringProperty(name="Last Error", default="", options={"SKIP_SAVE"}),
    }


FRACTERRA_PG_terrain.__annotations__ = {
    **editable_annotations("terrain"),
    **terrain_annotations(_on_setting_changed),
    # Picking an erosion preset fills the erosion settings, then regenerates as any change does.
    "erode_preset": erosion_layout.preset_property(then=_on_setting_changed),
}


def copy_settings(src, dst, param_list=None):
    """Copies every setting (terrain unless another list is given) between operators and PropertyGroups."""
    for p in param_list or params.TERRAIN_OBJECT_PARAMS:
        setattr(dst, p.name, getattr(src, p.name))


_on_planet_setting_changed = live_update("is_planet", planet_build.preview_regenerate, restore_settings)


class FRACTERRA_PG_planet(bpy.types.PropertyGroup):
    """The settings of a fractal planet, kept on its object for re-editing."""


FRACTERRA_PG_planet.__annotations__ = {
    **editable_annotations("planet"),
    **terrain_annotations(_on_planet_setting_changed, params.PLANET_OBJECT_PARAMS),
}


_on_polyline_setting_changed = live_update("is_polyline", regenerate_polyline)


class FRACTERRA_PG_polyline(bpy.types.PropertyGroup):
    """The settings of a fractal polyline, kept on its object for re-editing."""


FRACTERRA_PG_polyline.__annotations__ = {
    "is_polyline": BoolProperty(name="Fractal Polyline", default=False,
                                description="This object was made by Add > Curve > Fractal Polyline"),
    "auto_update": BoolProperty(name="Auto Update", default=False,
                                description="Regenerate the polyline whenever a setting changes"),
    "last_error": StringProperty(name="Last Error", default="", options={"SKIP_SAVE"}),
    "base_nodes": StringProperty(name="Base Nodes", default="",
                                 description="The nodes of the object it was made along (JSON), in its own frame"),
    **terrain_annotations(_on_polyline_setting_changed, params.POLYLINE_PARAMS),
}


class FRACTERRA_PG_measures(bpy.types.PropertyGroup):
    """Measures of an object, filled by object.fracterra_measure (the panel only shows them)."""
    kind: StringProperty(name="Measured", default="", description="What was measured: terrain or polylines")
    hurst: FloatProperty(name="H", description="Hurst exponent, by the library's recommended estimator for the "
                                               "grid (the one `fracterra analyze` reports)")
    estimator: StringProperty(name="Estimator", default="", description="The Hurst estimator used")
    estimator_reason: StringProperty(name="Why", default="", description="Why the estimator was chosen")
    dimension: FloatProperty(name="D", description="Fractal dimension (terrain: 3 - H; polylines: box counting)")
    std_error: FloatProperty(name="Std Error", description="Standard error of the fitted slope")
    eta: FloatProperty(name="eta", description="Max deviation of the main line from its chord / chord length")
    chi: FloatProperty(name="chi", description="Mean deviation from the chord / chord length")
    gamma: FloatProperty(name="gamma", description="Line length / chord length (elongation)")
    geometry: StringProperty(name="Geometry", default="",
                             description="Fingerprint of the geometry that was measured: when the object's "
                                         "differs, the measures are shown as stale")
