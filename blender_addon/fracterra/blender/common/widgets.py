# SPDX-License-Identifier: GPL-3.0-or-later
"""Small drawing helpers shared by the panels and the preferences (a leaf module)."""

import math
import textwrap

from ... import core
from ...core import mesh_limits, params


# Characters of a label that the sidebar shows whole at its default width and
# Blender's default UI scale (tests/blender/test_addon.py checks every label).
SIDEBAR_CHARACTERS = 30
# What a label's icon takes of them: "Out of date: Seed, Strength" (27) beside
# the alert icon showed as "Out of date: Seed, Stren...".
ICON_CHARACTERS = 5


def draw_wrapped(layout, text, icon="NONE", width=SIDEBAR_CHARACTERS, alert=False):
    """`text` as wrapped labels (Blender labels do not wrap themselves); with an
    icon, every line is indented by it (BLANK1 under the first)."""
    col = layout.column(align=True)
    col.alert = alert
    for i, line in enumerate(textwrap.wrap(text, width - (ICON_CHARACTERS if icon != "NONE" else 0))):
        col.label(text=line, icon=icon if i == 0 else "BLANK1")


def draw_library_problem(layout):
    """Shows why the library cannot be used and what to do; False when it can."""
    ok, message = core.status()
    if not ok:
        draw_wrapped(layout.box(), message, icon="ERROR", alert=True)
    return not ok


def draw_size(layout, values):
    """For large terrains, the vertex and memory estimate, or why Blender cannot hold it."""
    nx, ny = params.grid_shape(values)
    reason = mesh_limits.too_large(nx, ny)
    if reason:
        draw_wrapped(layout, "Too large: " + reason, icon="ERROR", alert=True)
    elif nx * ny >= mesh_limits.SHOW_ESTIMATE_FROM:
        draw_wrapped(layout, mesh_limits.estimate(nx, ny), icon="INFO", width=SIDEBAR_CHARACTERS)


def unit_label(p, label=None):
    """The label of parameter `p` with the unit Blender cannot show in its field
    ("Step Length (years)", "Diffusion (x1e-7 world units^2/yr)")."""
    label = label or p.label
    if not p.unit_text:
        return label
    scale = f"x1e-{round(math.log10(p.display_scale))} " if p.display_scale else ""
    return f"{label} ({scale}{p.unit_text})"


# A length in metres from this on is shown in km (an Earth's radius read "6371000.00").
KM_FROM = 1e5


def shows_km(p):
    """True for a setting in metres whose values are shown in km (ui/properties.km_property)."""
    return p is not None and p.kind == "float" and p.unit_text == "metres" and p.default >= KM_FROM


def km_name(name):
    return f"{name}_km"


def draw_setting(layout, data, name, p=None):
    """A setting as a field; with a unit Blender cannot show (years, 1/yr, ...), its
    label and unit on a row above the field, wrapped to the narrow sidebar, so
    neither is cut off. A value too small for Blender's 6 decimals is drawn
    scaled (ui/properties.display_property), the scale with the unit; a large
    length in km."""
    shown = params.shown_name(name) if p is not None and p.display_scale else name
    if p is None or not p.unit_text:
        layout.prop(data, shown)
        return
    col = layout.column(align=True)
    if shows_km(p):
        draw_wrapped(col, f"{p.label} (km)")
        col.prop(data, km_name(name), text="")
        return
    draw_wrapped(col, unit_label(p))
    col.prop(data, shown, text="")


def draw_placement(layout, op):
    """Where an Add operator puts its object (AddObjectHelper's Align, Location, Rotation)."""
    col = layout.column()
    col.use_property_split = True
    col.prop(op, "align")
    col.prop(op, "location")
    col.prop(op, "rotation")
