# SPDX-License-Identifier: GPL-3.0-or-later
"""Rivers, lakes and the sea of a terrain as numpy arrays (fracterra/hydrology.h),
with the CLI's writers (GeoJSON, GeoPackage, CSV, JSON: the same files as
`fracterra rivers --out` / `--lakes`)."""

from __future__ import annotations

import ctypes
import os
from ctypes import POINTER, c_double

import numpy as np

from .core.binding import NetworkMeasures
from .core.rivers import LAND, SEA, RiverNetwork

_ENDS = ("confluence", "sea", "lake", "edge", "sink")
_VALUES = ("discharge", "width", "depth", "area")  # ft_river_network_vertex_values' order


class Rivers:
    """A river network, copied out of the library (the handle is kept for the writers):

    xyz (n, 3) float64: vertices in world units (x = column x spacing, y = row
    x spacing, z = the water surface); offsets (segments + 1,) int64: segment
    k is xyz[offsets[k]:offsets[k + 1]]; radii (n,) half widths; discharge,
    width, depth, area (n,) per vertex; order, downstream, stream, lake,
    from_lake (segments,) int32, end (segments,) str (confluence, sea, lake,
    edge, sink), length (segments,) float64; lakes: a dict of arrays (level,
    area, volume, outlet_x, outlet_y, outlet_segment, cells); lake_rings: a
    list per lake of (m, 3) shoreline rings (the first the outer one);
    water_mask (rows, columns) int32 on the terrain's grid: a lake's index,
    LAND (-1) or SEA (-2). segments(): the segments as a list of (m, 3) arrays.
    """

    LAND, SEA = LAND, SEA

    def __init__(self, net: RiverNetwork, terrain, carved: bool = False):
        self._net = RiverNetwork(net.handle)  # this object now owns the handle
        net.handle = None
        lib = self._net._lib
        with self._net.polylines() as pl:
            self.xyz = np.asarray(pl.xyz(), dtype=np.float64).reshape(-1, 3)
            self.radii = np.asarray(pl.radii(), dtype=np.float64)
            self.offsets = np.asarray(pl.offsets(), dtype=np.int64)
        n = len(self.xyz)
        for which, name in enumerate(_VALUES):
            out = np.empty(n, dtype=np.float64)
            lib.check(lib.ft_river_network_vertex_values(self._net.handle, which, out.ctypes.data_as(POINTER(c_double)), n))
            setattr(self, name, out)
        segs = self._net.segments()
        for name in ("order", "downstream", "stream", "lake", "from_lake"):
            setattr(self, name, np.array([getattr(s, name) for s in segs], dtype=np.int32))
        self.end = np.array([_ENDS[s.end] for s in segs], dtype=object)
        self.length = np.array([s.length for s in segs], dtype=np.float64)
        lakes = self._net.lakes()
        self.lakes = {name: np.array([getattr(lk, name) for lk in lakes],
                                     dtype=np.int32 if name in ("outlet_segment", "cells") else np.float64)
                      for name in ("level", "area", "volume", "outlet_x", "outlet_y", "outlet_segment", "cells")}
        self.lake_rings = self._rings(lakes)
        mask = self._net.water_mask()
        rows, cols = np.asarray(terrain).shape
        h, w = mask.shape
        # A torus's mask (one sample smaller a side) is wrapped back onto the terrain's grid.
        self.water_mask = mask if (h, w) == (rows, cols) else mask[np.arange(rows) % h][:, np.arange(cols) % w]
        self.world_size = float(getattr(terrain, "world_size", 0.0))
        self._terrain = None if carved else terrain  # a Build's terrain is carved already

    def carve(self):
        """The terrain these rivers were traced on, its ground lowered under each river to the
        river's depth (never below the sea; lakes and the sea untouched), as the pipeline's rivers
        stage returns it: ft.terrain(p, rivers=True).terrain is ft.rivers(ft.terrain(p)).carve(),
        bit for bit. A terrain that tiles is carved as its torus and still tiles."""
        from .arrays import Terrain, from_library, to_library
        lib = self._net._lib
        z = self._terrain
        if z is None:
            raise ValueError("these rivers came with ft.terrain(rivers=...), whose terrain is carved already")
        overlap = int(getattr(z, "period_overlap", -1))
        a = np.asarray(z)
        ws = self.world_size
        if overlap > 0:  # the torus it was traced on (pipeline.cpp's torus_of)
            a = a[:-overlap, :-overlap]
            ws = ws * (a.shape[1] - 1) / (z.shape[1] - 1)
        out = ctypes.c_void_p()
        with to_library(a, world_size=ws) as hf:
            lib.check(lib.ft_rivers_carve(hf.handle, self._net.handle, ctypes.byref(out)))
        from .core.terrain import Heightfield
        with Heightfield(out) as carved:
            c = np.asarray(from_library(carved))
        if overlap > 0:  # back on the full grid: the first row and column repeated as the last
            c = c[np.arange(z.shape[0]) % c.shape[0]][:, np.arange(z.shape[1]) % c.shape[1]]
        return Terrain(c, self.world_size, overlap, float(getattr(z, "sea_level", np.nan)))

    def _rings(self, lakes) -> list:
        from .core.polylines import Polylines
        out = ctypes.c_void_p()
        self._net._lib.check(self._net._lib.ft_river_network_lake_rings(self._net.handle, ctypes.byref(out)))
        with Polylines(out) as pl:
            xyz = np.asarray(pl.xyz(), dtype=np.float64).reshape(-1, 3)
            offsets = np.asarray(pl.offsets(), dtype=np.int64)
        rings = [xyz[offsets[k]:offsets[k + 1]] for k in range(len(offsets) - 1)]
        return [rings[lk.first_ring:lk.first_ring + lk.ring_count] for lk in lakes]

    @property
    def segment_count(self) -> int:
        return len(self.offsets) - 1

    @property
    def lake_count(self) -> int:
        return len(self.lakes["level"])

    def segments(self) -> list:
        return [self.xyz[self.offsets[k]:self.offsets[k + 1]] for k in range(self.segment_count)]

    def measures(self) -> dict:
        """The network's measures, as `fracterra rivers --stats` reports them: Horton's
        bifurcation and length ratios (with the standard errors of their logs) over the Strahler
        orders, streams and mean_length per order, total_length, land_area, drainage_density,
        Hack's h (hack_h, hack_h_stderr, hack_points), the counts and ends by kind."""
        lib = self._net._lib
        m = NetworkMeasures(struct_size=ctypes.sizeof(NetworkMeasures))
        lib.check(lib.ft_river_network_measures(self._net.handle, ctypes.byref(m)))
        out = {name: getattr(m, name) for name, _ in NetworkMeasures._fields_
               if name not in ("struct_size", "reserved0", "ends", "streams", "mean_length")}
        k = m.horton_orders
        out["streams"] = np.array(m.streams[:k], dtype=np.int64)
        out["mean_length"] = np.array(m.mean_length[:k], dtype=np.float64)
        out["ends"] = dict(zip(_ENDS, m.ends[:5]))
        return out

    def write(self, path, lakes_only: bool = False) -> None:
        """Writes the rivers and lakes to `path` by its extension, as `fracterra rivers --out`: .geojson
        (LineStrings with their properties), .gpkg (a rivers and a lakes layer), .csv or .json. With
        lakes_only=True, the lakes alone as `--lakes` writes them (.geojson, .gpkg or .json)."""
        lib = self._net._lib
        lib.check(lib.ft_river_network_write(self._net.handle, None, os.fsencode(os.fspath(path)),
                                             1 if lakes_only else 0))

    def to_geojson(self, path) -> None:
        """write() to a .geojson file."""
        self._write_as(path, ".geojson")

    def to_geopackage(self, path) -> None:
        """write() to a .gpkg file (a rivers and a lakes layer)."""
        self._write_as(path, ".gpkg")

    def _write_as(self, path, ext):
        if not os.fspath(path).lower().endswith(ext):
            raise ValueError(f"{os.fspath(path)!r}: give a {ext} path")
        self.write(path)

    def close(self) -> None:
        self._net.close()

    def __repr__(self):
        return f"<fracterra.Rivers: {self.segment_count} segments, {self.lake_count} lakes>"


__all__ = ["Rivers"]
