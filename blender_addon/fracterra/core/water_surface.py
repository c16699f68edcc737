# SPDX-License-Identifier: GPL-3.0-or-later
"""The water surface of lakes and the sea over a terrain's grid, cut to where
the water has depth (bpy-free, numpy). A surface flush with the ground
flickers against it (z-fighting), so the water is drawn only where it stands
more than the network's minimum depth over the ground, as the terrain mesh
draws the ground: two triangles a cell."""

import numpy as np

# The terrain's quads, corners 0-3 at (row, col), (row, col + 1), (row + 1,
# col + 1), (row + 1, col) (mesh.h's loop order), are drawn as two triangles
# 0-1-2 and 0-2-3, unless those face opposite ways (a fold sharper than a right
# angle, as along a carved bed): Blender then draws 0-1-3 and 1-2-3 in its view,
# and its BVH tree, another renderer or an exporter may split it either way.
# Water clipped to one split dipped under the other (by up to 7 cm on a 2 m
# mountain), so over such a cell it stands only where all four corners are deep.
_SPLIT_02 = (((0, 0), (0, 1), (1, 1)), ((0, 0), (1, 1), (1, 0)))  # (drow, dcol) per corner


def split_13(co):
    """Per cell ((ny - 1, nx - 1) bool): Blender draws it split along corners 1-3.
    `co`: (ny, nx, 3) float32 vertex positions of the terrain mesh. Blender's test
    (is_quad_flip_v3_first_third_fast), in float32 as Blender computes it."""
    co = np.asarray(co, dtype=np.float32)
    v1, v2, v3, v4 = co[:-1, :-1], co[:-1, 1:], co[1:, 1:], co[1:, :-1]
    d13 = v3 - v1
    a = np.cross(v2 - v1, d13)
    b = np.cross(v4 - v1, d13)
    return np.einsum("...k,...k->...", a, b) > 0


def depth_triangles(heights, rows, cols, level, min_depth, split13=None):
    """The water surface over the cells (rows, cols) at `level` (one per cell),
    cut to where it stands more than `min_depth` above the ground: each cell's
    two triangles (the terrain's) clipped to level - ground > min_depth (the
    ground is linear on a triangle, so the clipped part is deeper everywhere),
    slivers (area <= 1e-6 of a cell) dropped: POV-Ray refuses a
    mesh with a zero-area face whole. `split13`: split_13 of the terrain mesh
    (None: no cell is folded). Returns (n, 3, 2) float64 grid
    coordinates (column, row) and (n,) levels."""
    out_xy, out_z = [], []
    cells = np.ones(rows.size, dtype=bool)
    if split13 is not None:
        folded = split13[rows, cols]
        deep = np.ones(rows.size, dtype=bool)
        for dy, dx in ((0, 0), (0, 1), (1, 0), (1, 1)):
            deep &= level - heights[rows + dy, cols + dx] > min_depth
        cells = ~folded | deep  # a folded cell: whole where every corner is deep, else dry
    for tri in _SPLIT_02:
        if not cells.any():
            continue
        r, c, level_c = rows[cells], cols[cells], level[cells]
        gy = np.stack([r + dy for dy, _ in tri], axis=1).astype(np.float64)  # (m, 3)
        gx = np.stack([c + dx for _, dx in tri], axis=1).astype(np.float64)
        d = level_c[:, None] - heights[gy.astype(np.int64), gx.astype(np.int64)] - min_depth
        wet = d > 0
        count = wet.sum(axis=1)
        p = np.stack([gx, gy], axis=2)  # (m, 3, 2)
        # Whole triangles.
        full = count == 3
        out_xy.append(p[full]); out_z.append(level_c[full])
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
            lv = level_c[sel]
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
