# SPDX-License-Identifier: GPL-3.0-or-later
"""Blender data from and to library arrays: terrain meshes, polyline curves,
the Erode step's maps and material, the falloff mask, and reading a terrain
or curve object back. Imports core and common/ only."""
