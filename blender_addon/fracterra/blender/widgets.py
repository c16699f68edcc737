"""Small drawing helpers shared by the panels and the preferences (a leaf module)."""

import textwrap

from .. import core


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
