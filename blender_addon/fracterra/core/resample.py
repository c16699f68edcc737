# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference heights from images and DEMs of any size: the dyadic grid a
midpoint terrain's reference needs, by bilinear resampling (bpy-free; numpy,
which Blender always has)."""

import numpy as np


def dyadic_levels(size):
    """m when size = 2^m + 1 (m >= 1), else -1: the side of a (2^m + 1)^2 reference
    grid. The inverse of ft_terrain_side; the library's own check (terrain.cpp's
    dyadic_levels) is not exported, so this is the binding's one copy."""
    n = size - 1
    return n.bit_length() - 1 if size >= 3 and n & (n - 1) == 0 else -1


def resample_bilinear(image, size, rows=None):
    """`image` (h, w) resampled bilinearly to `rows` (default `size`) x `size`
    points spanning it corner to corner."""
    h, w = image.shape
    rows = size if rows is None else rows
    fx = np.arange(size, dtype=np.float64) / (size - 1) * (w - 1)
    fy = np.arange(rows, dtype=np.float64) / (rows - 1) * (h - 1)
    x0, y0 = fx.astype(np.int64), fy.astype(np.int64)
    x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)
    tx, ty = (fx - x0)[None, :], (fy - y0)[:, None]
    top = image[y0][:, x0] * (1 - tx) + image[y0][:, x1] * tx
    bottom = image[y1][:, x0] * (1 - tx) + image[y1][:, x1] * tx
    return top * (1 - ty) + bottom * ty
