# SPDX-License-Identifier: GPL-3.0-or-later
"""Where a terrain erodes and where rain falls, in Blender: the weights of a
vertex group painted on the terrain, or the brightness of an image, read in
the main thread (it needs bpy) and handed to the library's pipeline as
ft_erosion_params' erosion_mask and rain_map: (width, height, float32 values
in [0, 1]), row 0 at the terrain's row 0, spanning it corner to corner (the
library resamples bilinearly). A vertex group lives on the mesh: when a
rebuild swaps in a mesh of another grid (Preview to Final), carry_groups
paints the same weights onto it.
"""

import numpy as np

from ...core.resample import resample_bilinear
from ..common.images import image_luminance
from ..common.reporting import SettingsError
from .objects import mesh_grid

# The maps' setting prefixes and the names the sidebar gives them.
MAPS = {"erosion_mask": "Erosion mask", "rain_map": "Rain map"}
# Weights are read at most this many vertices a side (a Python loop over the
# vertices: 513^2 takes about a second); the library resamples bilinearly.
MAX_GROUP_SIDE = 513
# carry_groups writes weights in this many steps (one vertex_groups.add call each).
WEIGHT_STEPS = 256


def maps_for(values, obj):
    """{"erosion_mask": (width, height, float32 values) or None, "rain_map": ...}
    of terrain settings `values`; `obj` the terrain object (None: a new terrain,
    which has no vertex groups yet). None without erosion: nothing reads them."""
    if values.get("erode_preset", "NONE") == "NONE":
        return {what: None for what in MAPS}
    return {what: _map(values, what, obj) for what in MAPS}


def _map(values, what, obj):
    source, role = values.get(what + "_source", "NONE"), MAPS[what]
    if source == "NONE":
        return None
    if source == "IMAGE":
        name = values[what + "_image"]
        z = image_luminance(name, role)
        if z.shape[0] < 2 or z.shape[1] < 2:
            raise SettingsError(f"{role}: image '{name}' is {z.shape[1]} x {z.shape[0]} pixels; it needs at least "
                                "2 x 2, spanning the terrain")
        return z.shape[1], z.shape[0], np.ascontiguousarray(z, dtype=np.float32)
    z = group_weights(obj, values[what + "_group"], role)
    return z.shape[1], z.shape[0], np.ascontiguousarray(z, dtype=np.float32)


def group_weights(obj, name, role):
    """(rows, columns) float64 weights of vertex group `name` of terrain `obj`
    over its grid (0 where a vertex is not in the group), every vertex up to
    MAX_GROUP_SIDE a side, evenly spaced ones (corners included) beyond."""
    if obj is None:
        raise SettingsError(f"{role}: a new terrain has no vertex groups yet; add it, paint a vertex group "
                            "(Weight Paint), then choose it in the sidebar")
    group = obj.vertex_groups.get(name) if name else None
    if group is None:
        raise SettingsError(f"{role}: choose a vertex group of '{obj.name}' (got {name or 'nothing'!r}); paint one "
                            "in Weight Paint mode")
    grid = mesh_grid(obj)
    if grid is None:
        raise SettingsError(f"{role}: '{obj.name}' has {len(obj.data.vertices)} vertices, not its grid (edited?); "
                            "its vertex group cannot be read as a map")
    nx, ny = grid
    xs = np.round(np.linspace(0, nx - 1, min(nx, MAX_GROUP_SIDE))).astype(np.int64)
    ys = np.round(np.linspace(0, ny - 1, min(ny, MAX_GROUP_SIDE))).astype(np.int64)
    vertices, index = obj.data.vertices, group.index
    out = np.zeros((len(ys), len(xs)))
    for r, row in enumerate((ys * nx).tolist()):
        for c, x in enumerate(xs.tolist()):
            for g in vertices[row + x].groups:
                if g.group == index:
                    out[r, c] = g.weight
                    break
    return out


def carried_groups(values, maps):
    """{vertex group name: (rows, columns) weights} of the maps read from groups:
    what carry_groups paints on a rebuilt mesh."""
    return {values[what + "_group"]: np.frombuffer(m[2], dtype=np.float32).reshape(m[1], m[0])
            for what, m in maps.items() if m is not None and values.get(what + "_source") == "VERTEX_GROUP"}


def carry_groups(obj, groups, nx, ny):
    """Paints each group's weights, resampled to the nx x ny grid, onto terrain
    `obj`'s new mesh (a swapped-in mesh has no groups: they live on the mesh)."""
    for name, weights in groups.items():
        group = obj.vertex_groups.get(name) or obj.vertex_groups.new(name=name)
        w = resample_bilinear(np.asarray(weights, dtype=np.float64), nx, ny).ravel()
        steps = np.round(np.clip(w, 0.0, 1.0) * (WEIGHT_STEPS - 1)).astype(np.int64)
        order = np.argsort(steps, kind="stable")
        bounds = np.searchsorted(steps[order], np.arange(1, WEIGHT_STEPS + 1))
        for step in range(1, WEIGHT_STEPS):
            chosen = order[bounds[step - 1]:bounds[step]]
            if len(chosen):
                group.add(chosen.tolist(), step / (WEIGHT_STEPS - 1), "REPLACE")
