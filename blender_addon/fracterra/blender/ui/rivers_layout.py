# SPDX-License-Identifier: GPL-3.0-or-later
"""The Rivers and Lakes box of a terrain's settings (the sidebar's Rivers and
Lakes panel): the switch, then the settings of ft_hydrology_params that
Blender keeps (core.params.RIVERS_PARAMS), in the table's order."""

from ...core import params
from ..common.widgets import draw_setting


def draw_rivers(layout, data):
    """The switch, and the settings when it is on."""
    layout.prop(data, "rivers")
    if not data.rivers:
        return
    col = layout.column(align=True)
    for p in params.RIVERS_PARAMS[1:]:
        draw_setting(col, data, p.name, p)
