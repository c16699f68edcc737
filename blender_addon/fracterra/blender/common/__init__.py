# SPDX-License-Identifier: GPL-3.0-or-later
"""Leaves every role uses: reporting errors, long jobs with progress and Esc,
the preferences, reading images, shared drawing helpers, installing presets.
They import core and bpy only (and each other, downwards)."""
