"""Small drawing helpers shared by the panels and the preferences (a leaf module)."""

import textwrap

from ... import core
from ...core import mesh_limits, params


def draw_wrapped(layout, text, icon="NONE", width=60, alert=False):
    """`text` as wrapped labels (Blender labels do not wrap themselves)."""
    col = layout.column(align=True)
    col.alert = alert
    for i, line in enumerate(textwrap.wrap(text, width)):
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
        layout.label(text=mesh_limits.estimate(nx, ny), icon="INFO")
