# SPDX-License-Identifier: GPL-3.0-or-later
"""The water surface of lakes and the sea over a terrain's grid, cut to where
the water has depth (bpy-free, numpy). A surface flush with the ground
flickers against it (z-fighting), so the water is drawn only where it stands
more than the network's minimum depth over the ground, as the terrain mesh
draws the ground: two triangles a cell."""

import numpy as np

# The terrain's quads are drawn as two triangles split along the diagonal from
# corner (col, row) to (col + 1, row + 1) (mesh.h's loop order 0-1-2, 0-2-3,
# as Blender triangulates a quad).
_TRIANGLES = (((0, 0), (0, 1), (1, 1)), ((0, 0), (1, 1), (1, 0)))  # (drow, dcol) per corner


def depth_triangles(heights, rows, cols, level, min_depth):
    """The water surface over the cells (rows, cols) at `level` (one per cell),
    cut to where it stands more than `min_depth` above the ground: each cell's
    two triangles (the terrain's) clipped to level - ground > min_depth (the
    ground is linear on a triangle, so the clipped part is deeper everywhere),
    slivers (area <= 1e-6 of a cell) dropped: POV-Ray refuses a
    mesh with a zero-area face whole. Returns (n, 3, 2) float64 grid
    coordinates (column, row) and (n,) levels."""
    out_xy, out_z = [], []
    for tri in _TRIANGLES:
        gy = np.stack([rows + dy for dy, _ in tri], axis=1).astype(np.float64)  # (m, 3)
        gx = np.stack([cols + dx for _, dx in tri], axis=1).astype(np.float64)
        d = level[:, None] - heights[gy.astype(np.int64), gx.astype(np.int64)] - min_depth
        wet = d > 0
        count = wet.sum(axis=1)
        p = np.stack([gx, gy], axis=2)  # (m, 3, 2)
        # Whole triangles.
        full = count == 3
        out_xy.append(p[full]); out_z.append(level[full])
        # One or two corners deep: roll each triangle so corner 0 is the odd one out
        # (the deep corner of a one, the dry corner of a two), keeping the winding.
        for k in (1, 2):
            sel = count == k
            if not sel.any():
                continue
            ps, ds, ws = p[sel], d[sel], wet[sel]
            odd = ws if k == 1 else ~ws
            first = np.argmax(odd, axis=1)
            idx = (first[:, None] + np.arange(3)[None, :]) % 3
            ps = np.take_along_axis(ps, idx[:, :, None], axis=1)
            ds = np.take_along_axis(ds, idx, axis=1)
            # Where the edges from corner 0 cross depth min_depth.
            t1 = (ds[:, 0] / (ds[:, 0] - ds[:, 1]))[:, None]
            t2 = (ds[:, 0] / (ds[:, 0] - ds[:, 2]))[:, None]
            a = ps[:, 0] + t1 * (ps[:, 1] - ps[:, 0])
            b = ps[:, 0] + t2 * (ps[:, 2] - ps[:, 0])
            lv = level[sel]
            if k == 1:  # the deep corner's tip
                out_xy.append(np.stack([ps[:, 0], a, b], axis=1)); out_z.append(lv)
            else:  # the quad a, 1, 2, b
                out_xy.append(np.stack([a, ps[:, 1], ps[:, 2]], axis=1)); out_z.append(lv)
                out_xy.append(np.stack([a, ps[:, 2], b], axis=1)); out_z.append(lv)
    xy = np.concatenate(out_xy) if out_xy else np.zeros((0, 3, 2))
    z = np.concatenate(out_z) if out_z else np.zeros(0)
    e1, e2 = xy[:, 1] - xy[:, 0], xy[:, 2] - xy[:, 0]
    area = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])  # grid units^2
    keep = area > 1e-6
    return xy[keep], z[keep]
