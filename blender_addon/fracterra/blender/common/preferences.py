# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on's preferences (Edit > Preferences > Add-ons > Fracterra).

A leaf module: the builders and operators read the preferences from here,
and it imports nothing that imports them.
"""

import bpy

from ... import core
from .widgets import draw_library_problem, draw_wrapped

ROOT_PACKAGE = __package__.rsplit(".", 2)[0]  # the add-on: fracterra.blender.common -> fracterra


class FracterraPreferences(bpy.types.AddonPreferences):
    bl_idname = ROOT_PACKAGE

    # Default 1: a 1025^2 terrain takes ~20 ms on one core, while the library's
    # OpenMP threads, when a render or other programs keep every core busy, wait
    # at their barriers for hundreds of ms (measured 0.46 s vs 0.018 s here).
    threads: bpy.props.IntProperty(
        name="Threads", default=1, min=0, max=1024,
        description="Threads the library uses for generation (0: all cores; results never depend on it). "
                    "1 is fastest up to ~2049^2 and whenever other programs (renders) keep the cores busy")

    def draw(self, context):
        layout = self.layout
        if not draw_library_problem(layout):
            draw_wrapped(layout, core.status()[1], icon="CHECKMARK", width=60)
        layout.prop(self, "threads")


def preferences(context):
    """The add-on's preferences, or None when it runs unregistered from a script."""
    addon = context.preferences.addons.get(ROOT_PACKAGE)
    return addon.preferences if addon else None


def library_threads(context):
    """Threads for a library call: the preference, or 0 (all cores) without one."""
    prefs = preferences(context)
    return prefs.threads if prefs else 0
