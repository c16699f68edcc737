"""Flat arrays describing a terrain as a quad grid mesh, filled by the library.

The arrays are array.array buffers ready for Blender's `foreach_set` (which
copies them with memcpy; ctypes arrays would go through a slow path). The
index layout is documented in fracterra/mesh.h.
"""

import math
from ctypes import byref, c_float, c_int32

from .binding import GridCounts, library
from .terrain import as_pointer, float_array, index_array

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


def grid_counts(nx, ny):
    lib = library()
    c = GridCounts()
    lib.check(lib.ft_grid_counts_get(nx, ny, byref(c)))
    return c


def grid_size(world_size, nx, ny):
    """(world_size_x, world_size_y): X spans world_size, Y keeps the same sample spacing."""
    return world_size, world_size * (ny - 1) / (nx - 1)


def vertices(hf, world_size_x, world_size_y, z_floor=NO_FLOOR, out=None):
    """xyz of every vertex (array.array('f'), 3 per vertex); reuses `out` if given."""
    lib = library()
    n = 3 * hf.width * hf.height
    if out is None or len(out) != n:
        out = float_array(n)
    lib.check(lib.ft_grid_vertices(hf.handle, world_size_x, world_size_y, z_floor, as_pointer(out, c_float), len(out)))
    return out


def grid_arrays(hf, world_size, z_floor=NO_FLOOR, uvs=True, progress=None):
    """Everything needed to build the mesh of heightfield `hf` in one pass.
    progress: None or callable(fraction) after each array (a 4097^2 grid's
    take seconds together)."""
    lib = library()
    report = progress or (lambda _fraction: None)
    g = GridArrays(hf.width, hf.height)
    world_size_x, world_size_y = grid_size(world_size, g.nx, g.ny)
    g.co = vertices(hf, world_size_x, world_size_y, z_floor)
    report(0.2)
    g.loop_vertices, g.loop_edges = index_array(g.loop_count), index_array(g.loop_count)
    g.edge_vertices = index_array(2 * g.edge_count)
    g.loop_starts, g.loop_totals = index_array(g.face_count), index_array(g.face_count)
    lib.check(lib.ft_grid_topology(
        g.nx, g.ny, as_pointer(g.loop_vertices, c_int32), as_pointer(g.loop_edges, c_int32), g.loop_count,
        as_pointer(g.edge_vertices, c_int32), len(g.edge_vertices),
        as_pointer(g.loop_starts, c_int32), as_pointer(g.loop_totals, c_int32), g.face_count))
    report(0.7)
    if uvs:
        g.uv = float_array(2 * g.loop_count)
        lib.check(lib.ft_grid_uvs(g.nx, g.ny, as_pointer(g.uv, c_float), len(g.uv)))
    report(1.0)
    return g
