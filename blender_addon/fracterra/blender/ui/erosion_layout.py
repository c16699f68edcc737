# SPDX-License-Identifier: GPL-3.0-or-later
"""The Erode box of a terrain's settings (redo panel and sidebar), and the
preset menu whose choice fills the settings (build/erosion.py runs them).

An artist sees the preset, Strength and Duration; the landscape model's rates
wait under a collapsed Advanced. The library's extra passes after the run
(fluvial_steps, hydraulic_iterations, thermal_iterations and their rates) are
not the landscape model's: they stay settings (0 unless a script sets them)
but are not drawn.
"""

import bpy
from bpy.props import BoolProperty, EnumProperty

from ...core import erosion, params
from ..common.widgets import draw_setting

# What a preset sets (core.erosion.PRESET_FIELDS without the extra pass counts):
# Duration in the box, the model's rates under Advanced, in the order drawn.
MAIN = ("strength", "duration")
ADVANCED = ("erodibility", "area_exponent", "diffusion", "deposition", "talus_degrees", "scree_years", "rainfall")
SET_BY_PRESET = tuple(name for name in erosion.PRESET_FIELDS if name not in erosion.COUNTS)
# Where the Advanced fold's state lives: on the window manager, so opening it
# is no setting of the terrain (no undo step, no rebuild from the sidebar).
ADVANCED_OPEN = "fracterra_erosion_advanced"

# Names of the datablocks whose preset is being applied: their field updates
# wait, and the preset's own update runs once at the end (one rebuild with
# Auto Update, not one per field).
_applying = []


def _key(data):
    return data.as_pointer()


def apply_preset(data):
    """Shows the chosen preset's settings in `data` (operator or PropertyGroup),
    so that switching to Custom starts from them; None zeroes the run, Custom
    leaves everything."""
    preset = data.erode_preset
    if preset == "CUSTOM":
        return
    _applying.append(_key(data))
    try:
        if preset == "NONE":
            for name in erosion.COUNTS:
                setattr(data, name, 0)
            data.duration = 0.0
            return
        values = erosion.preset_values(preset.lower())
        for name in erosion.PRESET_FIELDS:
            setattr(data, name, values[name])
    finally:
        _applying.remove(_key(data))


def settle_preset(op):
    """An operator run with arguments (a script, a saved operator preset): its
    erosion preset's settings, except those the arguments set otherwise, which
    stay and make it Custom, as the same edits in the panel do (arguments set
    no update callbacks)."""
    preset = op.erode_preset
    given = {}
    if preset not in ("NONE", "CUSTOM"):
        values = erosion.preset_values(preset.lower())
        given = {name: getattr(op, name) for name in SET_BY_PRESET
                 if op.properties.is_property_set(name) and not _close(getattr(op, name), values[name])}
    apply_preset(op)
    if given:
        _applying.append(_key(op))
        try:
            for name, value in given.items():
                setattr(op, name, value)
            op.erode_preset = "CUSTOM"
        finally:
            _applying.remove(_key(op))


def _close(value, preset_value):
    """Equal to float32, what a Blender property keeps."""
    return abs(value - preset_value) <= 1e-6 * abs(preset_value)


def applying(data):
    """True while apply_preset writes `data`'s settings."""
    return _key(data) in _applying


def preset_property(then=None, options=None):
    """The erode_preset EnumProperty whose update applies the preset (then calls `then`)."""
    p = params.PARAMS_BY_NAME["erode_preset"]

    def update(self, context):
        if applying(self):  # made Custom by leaves_preset, which rebuilds itself
            return
        apply_preset(self)
        if then is not None:
            then(self, context)

    return EnumProperty(name=p.label, description=p.description, default=p.default,
                        items=[(ident, label, tip, number) for ident, label, tip, number in p.items],
                        update=update, **({"options": options} if options is not None else {}))


def leaves_preset(update=None):
    """The update of a setting a preset sets: changed by hand (not by
    apply_preset) under a preset, the preset becomes Custom, keeping every
    value, so the menu never names a preset the settings no longer are.
    Then `update` (the rebuild), once."""
    def on_change(self, context):
        if applying(self):
            return
        if self.erode_preset not in ("NONE", "CUSTOM") and not _is_presets(self):
            _applying.append(_key(self))
            try:
                self.erode_preset = "CUSTOM"
            finally:
                _applying.remove(_key(self))
        if update is not None:
            update(self, context)
    return on_change


def _is_presets(data):
    """True when every setting the preset sets holds the preset's value (to
    float32, what a Blender property keeps): copying or restoring a preset's
    settings leaves it a preset."""
    values = erosion.preset_values(data.erode_preset.lower())
    return all(_close(getattr(data, name), values[name]) for name in SET_BY_PRESET)


def register():
    setattr(bpy.types.WindowManager, ADVANCED_OPEN,
            BoolProperty(name="Advanced", default=False, options={"SKIP_SAVE"},
                         description="The landscape model's own rates: how soft the rock is, how rivers "
                                     "grow, creep, fans, the scree angle and the rainfall"))


def unregister():
    delattr(bpy.types.WindowManager, ADVANCED_OPEN)


# Blender's own short unit symbols ("m", "s"), for the narrow sidebar: "years"
# beside the number was cut to "ye..." there (the tooltip says "years").
_SHORT_UNITS = {"years": "yr"}


def _unit_row(layout, data, name, in_sidebar_too=True):
    """A setting whose unit Blender cannot show (years, 1/yr) as its label, the
    number and the unit after it: "Duration | 100000 | years" ("yr" in the
    sidebar). The label in the field and the unit beside it cut "Duration" to
    "Dur" in the sidebar; there, unless `in_sidebar_too`, the label and unit
    go on a row above a full-width field ("Scree Angle | 40.00 | de" was cut)."""
    p = params.PARAMS_BY_NAME[name]
    wide = layout.use_property_split  # the redo panel; the sidebar draws without the split
    if not p.unit_text or p.display_scale or not (wide or in_sidebar_too) or len(p.unit_text) > len("degrees"):
        draw_setting(layout, data, name, p)  # "world units/yr" beside the field was cut even there
        return
    row = layout.split(factor=0.4, align=True)
    label = row.row()
    label.alignment = "RIGHT" if wide else "LEFT"  # as the split layout's own labels
    label.label(text=p.label)
    value = row.split(factor=0.68 if wide else 0.78, align=True)
    value.prop(data, name, text="")
    value.label(text=p.unit_text if wide else _SHORT_UNITS.get(p.unit_text, p.unit_text))


def draw_erosion(layout, data, context=None):
    """The Erode box: the preset, Strength and Duration, then a collapsed
    Advanced with the landscape model's rates; for a terrain's own settings
    (the sidebar), where erosion acts and where rain falls (a new terrain has
    no vertex groups to paint yet)."""
    obj = data.id_data if isinstance(data, bpy.types.PropertyGroup) else None
    box = layout.box().column(align=True)
    # A heading, then the menu across the box: as one split row the narrow
    # sidebar cut its label to "Erosi..." (issue 17).
    box.label(text=params.PARAMS_BY_NAME["erode_preset"].label)
    box.prop(data, "erode_preset", text="")
    if data.erode_preset == "NONE":
        return
    col = box.column(align=True)
    for name in MAIN:
        _unit_row(col, data, name)
    if obj is not None:
        draw_maps(box, data, obj)
    wm = (context or bpy.context).window_manager
    is_open = getattr(wm, ADVANCED_OPEN, False)
    row = box.row()
    row.use_property_split = False  # a fold's header, left-aligned in the redo panel too
    row.alignment = "LEFT"
    row.prop(wm, ADVANCED_OPEN, icon="TRIA_DOWN" if is_open else "TRIA_RIGHT", emboss=False)
    if is_open:
        col = box.column(align=True)
        for name in ADVANCED:
            _unit_row(col, data, name, in_sidebar_too=False)


def draw_maps(layout, data, obj):
    """The erosion mask and the rain map: each from a vertex group of the terrain or an image."""
    for what in ("erosion_mask", "rain_map"):
        col = layout.column(align=True)
        source = getattr(data, what + "_source")
        split = col.split(factor=0.4, align=True)
        split.label(text=params.PARAMS_BY_NAME[what + "_source"].label)
        split.prop(data, what + "_source", text="")
        if source == "VERTEX_GROUP":
            col.prop_search(data, what + "_group", obj, "vertex_groups", text="")
        elif source == "IMAGE":
            row = col.row(align=True)
            row.prop(data, what + "_image_pick", text="")
            op = row.operator("object.fracterra_reference_image_open", text="", icon="FILEBROWSER")
            op.target = what.upper()
