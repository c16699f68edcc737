# SPDX-License-Identifier: GPL-3.0-or-later
"""Blender images as arrays: the brightness that reference heights and
falloff masks are read from (a leaf: bpy, numpy and reporting only)."""

import bpy
import numpy as np

from .reporting import SettingsError


def luminance(pixels):
    """Rec. 709 luminance of an (h, w, channels) float array (one channel: itself), in float64."""
    px = pixels.astype(np.float64)
    if px.shape[2] >= 3:
        return 0.2126 * px[:, :, 0] + 0.7152 * px[:, :, 1] + 0.0722 * px[:, :, 2]
    return px[:, :, 0]


def image_luminance(name, role):
    """(h, w) float64 luminance of image `name`, row 0 the image's bottom row.
    `role` names the setting in the messages (e.g. "Reference")."""
    image = bpy.data.images.get(name) if name else None
    if image is None:
        raise SettingsError(f"{role}: choose an image for 'Image' (got {name or 'nothing'!r})")
    w, h = image.size
    if w < 1 or h < 1:
        raise SettingsError(f"{role} image '{image.name}' has no pixels (is the file missing?)")
    channels = image.channels
    px = np.empty(w * h * channels, dtype=np.float32)
    image.pixels.foreach_get(px)
    return luminance(px.reshape(h, w, channels))
