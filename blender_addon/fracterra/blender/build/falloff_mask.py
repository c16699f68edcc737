# SPDX-License-Identifier: GPL-3.0-or-later
"""The custom edge falloff's mask in Blender (the library's FT_FALLOFF_CUSTOM):
the brightness of an image, or the top-view silhouette of a mesh or curve
object over the terrain's footprint, optionally faded inward over the
falloff width. Read in the main thread (it needs bpy); the result goes to
core.generate_terrain(falloff_mask=(width, height, float32 values)), row 0 at
the terrain's row 0 (its -y edge), values in [0, 1]: 1 keeps the height,
0 gives the edge level. Windows and the whole sample it alike (the library
resamples it at each sample's place in the whole terrain).
"""

import bpy
import numpy as np

from ...core.grid import grid_size
from ...core.params import grid_shape
from ..common.images import image_luminance
from ..common.reporting import SettingsError

# An object's silhouette is drawn at the terrain's own resolution up to this
# many samples a side (the library resamples it bilinearly beyond that).
MAX_OBJECT_MASK_SIDE = 1025
OBJECT_TYPES = {"MESH", "CURVE", "SURFACE", "FONT", "META"}


def mask_for(values, frame, depsgraph, terrain_name=None):
    """(width, height, float32 values) for terrain settings `values`, or None
    when the falloff is not custom. `frame`: the terrain's world matrix (the
    footprint the object is projected on); `terrain_name`: the terrain object
    itself, which cannot be its own mask."""
    if values["falloff"] != "CUSTOM":
        return None
    if values["falloff_mask_source"] == "IMAGE":
        z = np.clip(image_luminance(values["falloff_mask_image"], "Falloff mask"), 0.0, 1.0)
        if z.shape[0] < 2 or z.shape[1] < 2:
            raise SettingsError(f"Falloff mask image '{values['falloff_mask_image']}' is {z.shape[1]} x "
                                f"{z.shape[0]} pixels; it needs at least 2 x 2")
        return z.shape[1], z.shape[0], np.ascontiguousarray(z, dtype=np.float32)
    name = values["falloff_mask_object"]
    obj = bpy.data.objects.get(name) if name else None
    if obj is None or obj.type not in OBJECT_TYPES:
        raise SettingsError(f"Falloff mask: choose a mesh or curve object for 'Mask Object' (got {name or 'nothing'!r})")
    if terrain_name is not None and obj.name == terrain_name:
        raise SettingsError(f"Falloff mask: '{obj.name}' is the terrain itself; choose another object, e.g. a "
                            "filled curve drawn over it")
    nx, ny = grid_shape(values)
    size_x, size_y = grid_size(values["world_size"], nx, ny)
    scale = min(1.0, (MAX_OBJECT_MASK_SIDE - 1) / (max(nx, ny) - 1))
    mw, mh = max(2, round((nx - 1) * scale) + 1), max(2, round((ny - 1) * scale) + 1)
    inside = object_silhouette(obj, frame, depsgraph, size_x, size_y, mw, mh).astype(np.float64)
    if values["falloff_mask_soft"]:
        inside = soft_edge(inside, values["falloff_width"] * (mw - 1) / 2)
    return mw, mh, np.ascontiguousarray(inside, dtype=np.float32)


def _object_geometry(obj, frame, depsgraph):
    """(xy of the vertices in the terrain's frame, triangles, edges) of the evaluated object."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        n = len(mesh.vertices)
        co = np.empty(3 * n, dtype=np.float64)
        mesh.vertices.foreach_get("co", co)
        m = np.array(frame.inverted() @ evaluated.matrix_world)
        co = co.reshape(n, 3) @ m[:3, :3].T + m[:3, 3]
        mesh.calc_loop_triangles()
        tris = np.empty(3 * len(mesh.loop_triangles), dtype=np.int64)
        mesh.loop_triangles.foreach_get("vertices", tris)
        edges = np.empty(2 * len(mesh.edges), dtype=np.int64)
        mesh.edges.foreach_get("vertices", edges)
    finally:
        evaluated.to_mesh_clear()
    return co[:, :2], tris.reshape(-1, 3), edges.reshape(-1, 2)


def object_silhouette(obj, frame, depsgraph, size_x, size_y, mw, mh):
    """(mh, mw) booleans: which of the mask's nodes (spanning the terrain's
    footprint corner to corner) the object covers seen from above. Faces are
    filled (their union); an object without faces (a curve without fill)
    gives the inside of its closed outlines (even-odd)."""
    xy, tris, edges = _object_geometry(obj, frame, depsgraph)
    # Node (i, j) sits at x = -size_x / 2 + i size_x / (mw - 1): in index units.
    px = (xy[:, 0] + size_x / 2) * (mw - 1) / size_x
    py = (xy[:, 1] + size_y / 2) * (mh - 1) / size_y
    if len(tris):
        return _fill_triangles(px[tris], py[tris], mw, mh)
    if len(edges):
        degree = np.bincount(edges.ravel(), minlength=len(xy))
        if np.any(degree[degree > 0] % 2):
            raise SettingsError(f"Falloff mask object '{obj.name}' has no faces and its outline is not closed: "
                                "close the curve (Alt+C), set its Fill Mode to Both, or give it faces")
        return _fill_outlines(px[edges], py[edges], mw, mh)
    raise SettingsError(f"Falloff mask object '{obj.name}' has no faces or edges seen from above")


def _spans(lo, hi, mw):
    """Covered nodes of one row: the union of the intervals [lo_k, hi_k]."""
    start = np.clip(np.ceil(lo), 0, mw).astype(np.int64)
    end = np.clip(np.floor(hi) + 1, 0, mw).astype(np.int64)
    keep = start < end
    diff = np.bincount(start[keep], minlength=mw + 1)[:mw + 1] - np.bincount(end[keep], minlength=mw + 1)[:mw + 1]
    return np.cumsum(diff)[:mw] > 0


def _fill_triangles(tx, ty, mw, mh):
    """Nodes inside any triangle ((T, 3) corner coordinates in index units): per
    row, each triangle the row crosses covers one interval of it."""
    out = np.zeros((mh, mw), dtype=bool)
    ymin, ymax = ty.min(axis=1), ty.max(axis=1)
    a, b = tx, ty
    a2, b2 = np.roll(tx, -1, axis=1), np.roll(ty, -1, axis=1)  # each corner's next: the three edges
    for j in range(max(0, int(np.ceil(ymin.min()))), min(mh - 1, int(np.floor(ymax.max()))) + 1):
        k = (ymin <= j) & (ymax >= j)
        if not k.any():
            continue
        x0, y0, x1, y1 = a[k], b[k], a2[k], b2[k]
        crosses = (np.minimum(y0, y1) <= j) & (np.maximum(y0, y1) >= j)
        dy = np.where(y1 != y0, y1 - y0, 1.0)
        x = np.where(y1 != y0, x0 + (j - y0) * (x1 - x0) / dy, np.minimum(x0, x1))
        x_hi = np.where(y1 != y0, x, np.maximum(x0, x1))  # a level edge on the row: all of it
        lo = np.where(crosses, x, np.inf).min(axis=1)
        hi = np.where(crosses, x_hi, -np.inf).max(axis=1)
        out[j] = _spans(lo, hi, mw)
    return out


def _fill_outlines(ex, ey, mw, mh):
    """Nodes inside closed outlines ((E, 2) edge end coordinates), even-odd."""
    out = np.zeros((mh, mw), dtype=bool)
    y0, y1, x0, x1 = ey[:, 0], ey[:, 1], ex[:, 0], ex[:, 1]
    for j in range(mh):
        k = ((y0 <= j) & (j < y1)) | ((y1 <= j) & (j < y0))  # half-open: a shared vertex counts once
        if not k.any():
            continue
        xs = np.sort(x0[k] + (j - y0[k]) * (x1[k] - x0[k]) / (y1[k] - y0[k]))
        out[j] = _spans(xs[0::2], xs[1::2], mw)
    return out


def _box_blur(a, r, axis):
    """Mean over 2r + 1 samples along `axis`, edges repeated."""
    n = a.shape[axis]
    pad = [(0, 0), (0, 0)]
    pad[axis] = (r + 1, r)
    c = np.cumsum(np.pad(a, pad, mode="edge"), axis=axis)
    return (np.take(c, np.arange(2 * r + 1, 2 * r + 1 + n), axis=axis) - np.take(c, np.arange(n), axis=axis)) / (2 * r + 1)


def soft_edge(inside, width):
    """0/1 `inside` faded inward over `width` nodes: 0 on and outside the outline,
    1 from `width` inside it, a smoothstep between (like the square and radial
    falloffs). A box blur of radius `width` ramps linearly across a straight
    outline from 0 at -width to 1 at +width; keeping its upper half moves the
    ramp inside. Outside the terrain the mask continues as at its edge, so a
    silhouette that covers an edge does not fall there."""
    r = int(round(width))
    if r < 1:
        return inside
    b = _box_blur(_box_blur(inside, r, 0), r, 1)
    t = np.clip(2 * b - 1, 0.0, 1.0)
    return t * t * (3 - 2 * t)
