# SPDX-License-Identifier: GPL-3.0-or-later
"""Flat arrays describing a terrain as a quad grid mesh, filled by the library.

The arrays are contiguous numpy buffers (float32; uint32 indices) that
Blender's `foreach_set` copies with memcpy: its fast path needs a buffer
whose format is the property's ('f', and 'I' for the unsigned index
properties); anything else goes element by element, about 10x slower. numpy
rather than array.array because numpy asks the kernel for huge pages for
large buffers: a 1025^2 grid's 150 MB then faults in 2 MB pages, not 4 kB
ones (docs/measurements/speed.md). The index layout is documented in
fracterra/mesh.h.
"""

import math
from ctypes import POINTER, byref, c_float, c_int32

from .binding import GridCounts, library
from .errors import FT_ERR_CANCELLED, CancelledError

NO_FLOOR = -math.inf


class GridArrays:
    """co (3 per vertex), edge_vertices (2 per edge), loop_vertices/loop_edges
    (1 per loop), loop_starts/loop_totals (1 per face), uv (2 per loop or None)."""

    def __init__(self, nx, ny):
        self.nx, self.ny = nx, ny
        c = grid_counts(nx, ny)
        self.vertex_count, self.edge_count, self.face_count, self.loop_count = (
            c.vertices, c.edges, c.faces, c.loops)
        self.co = None
        self.uv = None


def _buffer(n, dtype):
    """An uninitialised contiguous numpy array of n elements (the library fills it)."""
    # numpy here, not at the top: the rest of core is numpy-free, and scripts
    # run by a Python without numpy (examples/maps_montage.py) import it.
    import numpy as np  # pylint: disable=import-outside-toplevel
    return np.empty(n, dtype=dtype)


def _pointer(buf, ctype):
    """A ctypes pointer to numpy array `buf`'s data (None when empty: the library's NULL)."""
    return buf.ctypes.data_as(POINTER(ctype)) if len(buf) else None


def grid_counts(nx, ny):
    lib = library()
    c = GridCounts()
    lib.check(lib.ft_grid_counts_get(nx, ny, byref(c)))
    return c


def grid_size(world_size, nx, ny):
    """(world_size_x, world_size_y): X spans world_size, Y keeps the same sample spacing."""
    return world_size, world_size * (ny - 1) / (nx - 1)


def vertices(hf, world_size_x, world_size_y, z_floor=NO_FLOOR, out=None):
    """xyz of every vertex (float32 numpy array, 3 per vertex); reuses `out` if given."""
    lib = library()
    n = 3 * hf.width * hf.height
    if out is None or len(out) != n:
        out = _buffer(n, "float32")
    lib.check(lib.ft_grid_vertices(hf.handle, world_size_x, world_size_y, z_floor, _pointer(out, c_float), len(out)))
    return out


def grid_arrays(hf, world_size, z_floor=NO_FLOOR, uvs=True, progress=None):
    """Everything needed to build the mesh of heightfield `hf` in one pass.
    progress: None or callable(fraction) after each array (a 4097^2 grid's
    take seconds together)."""
    lib = library()
    report = progress or (lambda _fraction: None)
    g = GridArrays(hf.width, hf.height)
    world_size_x, world_size_y = grid_size(world_size, g.nx, g.ny)
    # All the arrays are views of one block: freed together, the block is one
    # run of huge-page memory that Blender's own copy of the mesh (the
    # depsgraph's, right after the build) can reuse whole.
    sizes = {"co": 3 * g.vertex_count, "loop_vertices": g.loop_count, "loop_edges": g.loop_count,
             "edge_vertices": 2 * g.edge_count, "loop_starts": g.face_count, "loop_totals": g.face_count,
             "uv": 2 * g.loop_count if uvs else 0}
    block = _buffer(sum(sizes.values()), "uint32")  # the library's int32 in 0..2^31-1: same bits
    start = 0
    for name, n in sizes.items():
        view = block[start:start + n]
        start += n
        setattr(g, name, view.view("float32") if name in ("co", "uv") else view)
    g.uv = g.uv if uvs else None
    vertices(hf, world_size_x, world_size_y, z_floor, out=g.co)
    report(0.2)
    # The topology an array at a time (ft_grid_topology skips a NULL buffer),
    # with a report after each: all at once took 2.7 s of a 4097^2 build at
    # load 4-6 without one.
    parts = (("loop_vertices",), ("loop_edges",), ("edge_vertices",), ("loop_starts", "loop_totals"))
    for k, names in enumerate(parts):
        p = {name: _pointer(getattr(g, name), c_int32) for name in names}
        lib.check(lib.ft_grid_topology(g.nx, g.ny, p.get("loop_vertices"), p.get("loop_edges"), g.loop_count,
                                       p.get("edge_vertices"), 2 * g.edge_count, p.get("loop_starts"),
                                       p.get("loop_totals"), g.face_count))
        report(0.2 + 0.5 * (k + 1) / len(parts))
    if uvs:
        lib.check(lib.ft_grid_uvs(g.nx, g.ny, _pointer(g.uv, c_float), len(g.uv)))
    report(1.0)
    return g


def height_slope(co, nx, ny, progress=None, bands=16):
    """The height and slope attributes of a grid mesh from its vertex positions
    `co` (3 floats per vertex, rows of nx along X), float32, one per vertex:
    the height 0..1 over the terrain's own range (so one material fits any
    size and sea level), the slope angle over 90 degrees. Computed in
    `bands` bands of rows with a report after each (the whole 4097^2 grid
    at once took 4.6 s in one step of Blender's main thread), by the same
    differences as numpy.gradient over the whole grid, central inside and
    one-sided at the edges: the same numbers to the bit. progress: None or
    callable(fraction) -> True to stop (raises CancelledError)."""
    import numpy as np  # pylint: disable=import-outside-toplevel (see _buffer)

    report = progress or (lambda _fraction: False)
    xyz = np.frombuffer(co, dtype=np.float32).reshape(ny, nx, 3)
    z = xyz[:, :, 2]
    low, high = float(z.min()), float(z.max())
    span = high - low
    dx = (float(xyz[0, -1, 0]) - float(xyz[0, 0, 0])) / (nx - 1)
    dy = (float(xyz[-1, 0, 1]) - float(xyz[0, 0, 1])) / (ny - 1)
    height = np.empty((ny, nx), dtype=np.float32)
    slope = np.empty((ny, nx), dtype=np.float32)
    for b in range(bands):
        r0, r1 = ny * b // bands, ny * (b + 1) // bands
        if r0 == r1:
            continue
        a0, a1 = max(r0 - 1, 0), min(r1 + 1, ny)  # with the rows either side
        zb = z[a0:a1].astype(np.float64)
        rows = zb[r0 - a0:r1 - a0]
        height[r0:r1] = (rows - low) / span if span > 0 else 0.0
        gx = np.empty_like(rows)
        if nx > 1:
            gx[:, 1:-1] = (rows[:, 2:] - rows[:, :-2]) / (2.0 * dx)
            gx[:, 0] = (rows[:, 1] - rows[:, 0]) / dx
            gx[:, -1] = (rows[:, -1] - rows[:, -2]) / dx
        gy = np.empty_like(rows)
        i0, i1 = max(r0, 1), min(r1, ny - 1)  # the band's inner rows
        if i1 > i0:
            gy[i0 - r0:i1 - r0] = (zb[i0 + 1 - a0:i1 + 1 - a0] - zb[i0 - 1 - a0:i1 - 1 - a0]) / (2.0 * dy)
        if r0 == 0:
            gy[0] = (zb[1 - a0] - zb[-a0]) / dy
        if r1 == ny:
            gy[-1] = (zb[ny - 1 - a0] - zb[ny - 2 - a0]) / dy
        slope[r0:r1] = np.arctan(np.hypot(gx, gy)) / (np.pi / 2)
        if report((b + 1) / bands):
            raise CancelledError("height and slope: cancelled", FT_ERR_CANCELLED)
    return height.ravel(), slope.ravel()
