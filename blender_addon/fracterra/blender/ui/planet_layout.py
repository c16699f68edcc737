# SPDX-License-Identifier: GPL-3.0-or-later
"""How a planet's settings are laid out, in the redo panel of Add > Mesh >
Fractal Planet and in the sidebar: the mesh's levels, the library's planet
settings that the method uses (from its table, so a new method or field needs
no case here), the sea, and how the planet stands in the scene."""

from ...core import params
from .settings_layout import setting_prop

_SEA = ("sea", "sea_level", "sea_fraction", "sea_sphere")
_SCENE = ("scene_radius", "vertical_scale")
_MESH = ("level", "preview_level")
# The variants that use Offset (the library's doc of the field names them).
_OFFSET_VARIANTS = ("RIDGED", "HYBRID", "HETERO")


def _shown(p, data):
    if p.name == "method" and len(p.items) < 2:
        return False  # nothing to choose
    if p.name == "offset" and getattr(data, "variant", None) not in _OFFSET_VARIANTS:
        return False
    return params.is_used(p, data.method)


def draw_planet_settings(layout, data, compact=False):
    """Lays out the settings of `data` (operator or PropertyGroup). `compact`
    (the sidebar): labels inside the fields."""
    by_name = {p.name: p for p in params.PLANET_OBJECT_PARAMS}

    def prop(lay, name):
        setting_prop(lay, data, name, by_name[name])

    col = layout.column(align=False)
    col.use_property_split = not compact
    col.use_property_decorate = False
    sub = col.column(align=True)
    prop(sub, "level")
    sub.label(text=f"Final: {6 * 4 ** data.level + 2:,} vertices", icon="MESH_UVSPHERE")
    prop(sub, "preview_level")
    sub = col.column(align=True)
    for p in params.PLANET_PARAMS:
        if p.name not in _SEA and _shown(p, data):
            prop(sub, p.name)
    box = col.box().column(align=True)
    box.label(text="Sea")
    prop(box, "sea")
    if data.sea == "HEIGHT":
        prop(box, "sea_level")
    elif data.sea == "FRACTION":
        prop(box, "sea_fraction")
    if data.sea != "NONE":
        prop(box, "sea_sphere")
    box = col.box().column(align=True)
    box.label(text="Scene")
    for name in _SCENE:
        prop(box, name)
