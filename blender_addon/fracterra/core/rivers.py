# SPDX-License-Identifier: GPL-3.0-or-later
"""Rivers, lakes and the sea of a terrain (fracterra/hydrology.h), as the last
stage of the library's pipeline (ft_terrain_build_rivers, pipeline.h): the
library decides the torus rule (a terrain that tiles gives rivers that wrap)
and the sea (the terrain's own), so the add-on and `fracterra terrain
--rivers` cannot disagree. bpy-free: the network is copied out into numpy
arrays (WaterArrays) in the job's worker thread, and the handle is freed.
"""

import ctypes
from ctypes import Structure, byref, c_double, c_int32, c_int64, c_void_p

from .handle import LibraryHandle
from .polylines import Polylines


class RiverSegment(Structure):
    """ft_river_segment (hydrology.h)."""
    _fields_ = [("first_vertex", c_int64), ("vertex_count", c_int64), ("order", c_int32),
                ("downstream", c_int32), ("end", c_int32), ("lake", c_int32), ("from_lake", c_int32),
                ("stream", c_int32), ("length", c_double)]


class Lake(Structure):
    """ft_lake (hydrology.h)."""
    _fields_ = [("level", c_double), ("area", c_double), ("volume", c_double), ("outlet_x", c_double),
                ("outlet_y", c_double), ("outlet_segment", c_int32), ("cells", c_int32),
                ("first_ring", c_int64), ("ring_count", c_int64)]


# Cells of the water mask (ft_river_network_water_mask): a lake's index, or these.
LAND, SEA = -1, -2


class RiverNetwork(LibraryHandle):
    """Owns an ft_river_network*."""

    _free = "ft_river_network_free"

    @property
    def segment_count(self):
        return self._lib.ft_river_network_segment_count(self.handle)

    @property
    def lake_count(self):
        return self._lib.ft_river_network_lake_count(self.handle)

    def polylines(self):
        """The rivers, one polyline per segment (radius: half the width); a new Polylines."""
        out = c_void_p()
        self._lib.check(self._lib.ft_river_network_polylines(self.handle, byref(out)))
        return Polylines(out)

    def ribbon_lines(self):
        """The rivers as drawn (ABI 2.28): each segment's line cut where its ribbon (half
        width to each side, flat ends) would reach into a lake's shoreline, each part a
        polyline of its own; a new Polylines. polylines() keeps the whole lines."""
        out = c_void_p()
        self._lib.check(self._lib.ft_river_network_ribbon_lines(self.handle, byref(out)))
        return Polylines(out)

    def segments(self):
        n = self.segment_count
        out = (RiverSegment * n)()
        self._lib.check(self._lib.ft_river_network_segments(self.handle, ctypes.cast(out, c_void_p), n))
        return list(out)

    def lakes(self):
        n = self.lake_count
        out = (Lake * n)()
        self._lib.check(self._lib.ft_river_network_lakes(self.handle, ctypes.cast(out, c_void_p), n))
        return list(out)

    def grid(self):
        """(width, height) of the grid it was traced on (a tiling terrain's torus)."""
        w, h = c_int32(), c_int32()
        self._lib.check(self._lib.ft_river_network_grid(self.handle, byref(w), byref(h)))
        return w.value, h.value

    @property
    def min_depth(self):
        """The minimum water depth it was traced with, world units (ABI 2.27)."""
        out = c_double()
        self._lib.check(self._lib.ft_river_network_min_depth(self.handle, byref(out)))
        return out.value

    def water_mask(self):
        """(height, width) int32 over the network's grid: a lake's index, LAND or SEA."""
        import numpy as np  # numpy only where water is asked for: core imports without it
        width, height = self.grid()
        out = np.empty(width * height, dtype=np.int32)
        self._lib.check(self._lib.ft_river_network_water_mask(
            self.handle, out.ctypes.data_as(ctypes.POINTER(c_int32)), out.size))
        return out.reshape(height, width)


class WaterArrays:
    """A river network copied out for Blender, on the terrain's grid (nx x ny
    samples; a network traced on the torus of a tiling terrain, one sample
    smaller a side, is wrapped back onto it):

    xyz (n, 3) float64 world units (x = column x spacing, y = row x spacing,
    z = water surface), radii (n,) half widths, offsets (segments + 1,),
    orders (segments,) Strahler orders; ribbon_xyz, ribbon_radii, ribbon_offsets:
    the same lines as drawn, cut where a ribbon would reach into a lake (one
    line or more per segment, or none); mask (ny, nx) int32: a lake's index,
    LAND or SEA; levels (lakes,) each lake's water level; spacing; min_depth:
    water shallower than this is not drawn (world units)."""

    def __init__(self, net, nx, ny, spacing):
        import numpy as np  # as in water_mask
        with net.polylines() as pl:
            self.xyz = np.asarray(pl.xyz(), dtype=np.float64).reshape(-1, 3)
            self.radii = np.asarray(pl.radii(), dtype=np.float64)
            self.offsets = np.asarray(pl.offsets(), dtype=np.int64)
        with net.ribbon_lines() as pl:
            self.ribbon_xyz = np.asarray(pl.xyz(), dtype=np.float64).reshape(-1, 3)
            self.ribbon_radii = np.asarray(pl.radii(), dtype=np.float64)
            self.ribbon_offsets = np.asarray(pl.offsets(), dtype=np.int64)
        self.orders = np.array([s.order for s in net.segments()], dtype=np.int32)
        self.levels = np.array([lake.level for lake in net.lakes()], dtype=np.float64)
        self.spacing = spacing
        self.min_depth = net.min_depth
        self.nx, self.ny = nx, ny
        mask = net.water_mask()
        h, w = mask.shape
        # A torus is wrapped back onto the grid: the last row and column repeat the first.
        self.mask = mask if (w, h) == (nx, ny) else mask[np.arange(ny) % h][:, np.arange(nx) % w]

    @property
    def segment_count(self):
        return len(self.offsets) - 1

    @property
    def lake_count(self):
        return len(self.levels)


__all__ = ["RiverNetwork", "RiverSegment", "Lake", "WaterArrays", "LAND", "SEA"]
