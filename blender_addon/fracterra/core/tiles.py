# SPDX-License-Identifier: GPL-3.0-or-later
"""Tile sets: a terrain larger than memory written as tiles, and read back.

The library does the tile logic (fracterra/tiles.h). This module holds its
binding, which the add-on's File > Import > Tile Set and Build Tile Set and
the Python package's Dask driver (fracterra.tiles, `python3 -m
fracterra.tiles`) share: the tile set handle (which refuses a folder holding
another terrain, erosion or maps and, for plain midpoint, bounds the common
height range from a coarse pass), and the pure per-tile tasks: write one tile
(under a temporary name, then renamed, so a task run twice writes the same
bytes), one tile's height range, one tile's increment sums for H. The add-on
carries no Dask code and no Dask CLI.

A set of an eroded terrain (or one with maps) is described by a recipe, a
plain dict that pickles to Dask workers: {"settings": terrain settings by
name, "reference": (size, values) or None, "falloff_mask", "erosion_mask",
"rain_map": (width, height, values) or None, "erosion": {setting: value} of
ft_erosion_params or None, "preset": an ft_build_params.erosion_preset id
("NONE", "LAND", ...), "maps": bool}. Its tiles are windows of what
ft_terrain_build makes of it, bit-identical to the whole.
"""

import ctypes
import json
import os
from ctypes import byref, c_double, c_int32, c_int64, c_size_t, c_uint32, c_void_p

from .binding import HurstResult, enum_values, library
from .erosion import MAPS, erosion_struct
from .errors import InvalidArgumentError
from .handle import LibraryHandle
from .terrain import Heightfield, attach_falloff_mask, attach_map, attach_reference, terrain_struct

FORMATS = {"png16": 0, "tiff": 1}
HURST_METHODS = {"variogram_aligned": 2, "madogram_aligned": 3}


def _terrain(settings, reference):
    """(ft_terrain_params, buffer to keep alive) from settings by name and an optional
    reference grid (size, values)."""
    p = terrain_struct(settings)
    return p, attach_reference(p, reference)


def _format(fmt):
    if fmt not in FORMATS:
        raise InvalidArgumentError(f"the tile format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    return FORMATS[fmt]


def recipe(settings, reference=None, falloff_mask=None, erosion=None, preset="NONE", maps=False, erosion_mask=None,
           rain_map=None):
    """A tile set's recipe (see the module's doc), checked for its preset's name."""
    preset = (preset or "NONE").upper()
    presets = enum_values("build", "erosion_preset")
    if preset not in presets:
        raise InvalidArgumentError(f"the erosion preset must be one of {', '.join(p.lower() for p in presets)}, "
                                   f"got {preset.lower()!r}")
    return {"settings": dict(settings), "reference": reference, "falloff_mask": falloff_mask,
            "erosion": dict(erosion) if erosion is not None else None, "preset": preset, "maps": bool(maps),
            "erosion_mask": erosion_mask, "rain_map": rain_map}


def built(r):
    """Whether a recipe needs the pipeline's tile calls (erosion, maps or a mask), not just the generator's."""
    return (r["preset"] != "NONE" or r["erosion"] is not None or r["maps"] or r["falloff_mask"] is not None
            or r["erosion_mask"] is not None or r["rain_map"] is not None)


class _Build:
    """The ft_build_params of a recipe and every buffer it points into (keep this alive while it is used)."""

    def __init__(self, r):
        lib = library()
        self.terrain = terrain_struct(r["settings"])
        self._bufs = [attach_reference(self.terrain, r["reference"]),
                      attach_falloff_mask(self.terrain, r["falloff_mask"])]
        masks = r["erosion_mask"] is not None or r["rain_map"] is not None
        self.erosion = erosion_struct(r["erosion"]) if r["erosion"] is not None or masks else None
        self._bufs += [attach_map(self.erosion, "erosion_mask", r["erosion_mask"], "the erosion mask"),
                       attach_map(self.erosion, "rain_map", r["rain_map"], "the rain map")]
        self.params = lib.build_params_type()
        lib.check(lib.ft_build_params_init(byref(self.params)))
        self.params.terrain = ctypes.pointer(self.terrain)
        if self.erosion is not None:
            self.params.erosion = ctypes.pointer(self.erosion)
        self.params.erosion_preset = enum_values("build", "erosion_preset")[r["preset"]]
        self.params.threads = int(r["settings"].get("threads", 0) or 0)
        self.maps = 1 if r["maps"] else 0


def write_built_tile(col, row, recipe, tile, fmt, height_min, height_max, out_dir):
    """One tile task of a recipe's set (a Dask task): writes tile (col, row), and its maps when the set has
    them; returns (col, row, [CRC-32 of the heights, then of each map])."""
    lib = library()
    b = _Build(recipe)
    n = 1 + (len(MAPS) if b.maps else 0)
    crcs = (c_uint32 * n)()
    lib.check(lib.ft_tile_write_build(byref(b.params), tile, _format(fmt), b.maps, height_min, height_max,
                                      os.fsencode(out_dir), col, row, crcs, n))
    return col, row, list(crcs)


def built_tile_range(col, row, recipe, tile, fmt, out_dir):
    """One task of a recipe's range pass: tile (col, row)'s (min, max); an eroded tile is kept in the set's
    folder for write_built_tile."""
    lib = library()
    b = _Build(recipe)
    lo, hi = c_double(), c_double()
    lib.check(lib.ft_tile_build_range(byref(b.params), tile, _format(fmt), b.maps, os.fsencode(out_dir), col, row,
                                      byref(lo), byref(hi)))
    return lo.value, hi.value


def write_tile(col, row, settings, reference, tile, fmt, height_min, height_max, out_dir):
    """One tile task (a Dask task on a worker): writes tile (col, row); returns (col, row, crc32)."""
    lib = library()
    p, _keep = _terrain(settings, reference)
    crc = c_uint32()
    lib.check(lib.ft_tile_write(byref(p), tile, _format(fmt), height_min, height_max, os.fsencode(out_dir), col, row,
                                byref(crc)))
    return col, row, crc.value


def tile_height_range(col, row, settings, reference, tile):
    """One task of the exact height-range pass: tile (col, row)'s (min, max)."""
    lib = library()
    p, _keep = _terrain(settings, reference)
    lo, hi = c_double(), c_double()
    lib.check(lib.ft_tile_height_range(byref(p), tile, col, row, byref(lo), byref(hi)))
    return lo.value, hi.value


class TileSet(LibraryHandle):
    """The driver's side of a tile set folder (ft_tileset*)."""

    _free = "ft_tileset_free"

    @classmethod
    def open(cls, settings, out_dir, tile=4096, fmt="png16", reference=None):
        lib = library()
        p, _keep = _terrain(settings, reference)
        out = c_void_p()
        lib.check(lib.ft_tileset_open(byref(p), tile, _format(fmt), os.fsencode(str(out_dir)), byref(out)))
        return cls(out)

    @classmethod
    def open_deferred(cls, settings, out_dir, tile=4096, fmt="png16", reference=None):
        """(set, pending): like open, but a new set needing the exact range pass is left pending
        (set_height_range gives it) instead of running that pass here."""
        lib = library()
        p, _keep = _terrain(settings, reference)
        out, pending = c_void_p(), c_int32()
        lib.check(lib.ft_tileset_open_deferred(byref(p), tile, _format(fmt), os.fsencode(str(out_dir)), byref(out),
                                               byref(pending)))
        return cls(out), bool(pending.value)

    @classmethod
    def open_build(cls, recipe, out_dir, tile=4096, fmt="png16", defer=True):
        """(set, pending) of a recipe's set (see the module's doc): a new eroded set is left pending for the
        range pass (built_tile_range per tile) unless defer is False."""
        lib = library()
        b = _Build(recipe)
        out, pending = c_void_p(), c_int32()
        lib.check(lib.ft_tileset_open_build(byref(b.params), tile, _format(fmt), b.maps, 1 if defer else 0,
                                            os.fsencode(str(out_dir)), byref(out), byref(pending)))
        return cls(out), bool(pending.value)

    def record_tile(self, col, row, crcs):
        """Records what write_built_tile returned (the heights' CRC-32, then each map's)."""
        arr = (c_uint32 * len(crcs))(*crcs)
        self._lib.check(self._lib.ft_tileset_record_tile(self.handle, col, row, arr, len(crcs)))

    def set_height_range(self, lo, hi):
        self._lib.check(self._lib.ft_tileset_set_height_range(self.handle, lo, hi))

    def grid(self):
        cols, rows = c_int32(), c_int32()
        self._lib.check(self._lib.ft_tileset_grid(self.handle, byref(cols), byref(rows)))
        return cols.value, rows.value

    def height_range(self):
        lo, hi = c_double(), c_double()
        self._lib.check(self._lib.ft_tileset_height_range(self.handle, byref(lo), byref(hi)))
        return lo.value, hi.value

    def done(self, col, row):
        d = c_int32()
        self._lib.check(self._lib.ft_tileset_tile_done(self.handle, col, row, byref(d)))
        return bool(d.value)

    def record(self, col, row, crc):
        self._lib.check(self._lib.ft_tileset_record(self.handle, col, row, crc))

    def finish(self):
        self._lib.check(self._lib.ft_tileset_finish(self.handle))


def manifest(folder):
    """The tile set's manifest.json as a dict (tile grid, height range, world size, tiles)."""
    path = os.path.join(str(folder), "manifest.json")
    try:
        with open(path, encoding="utf-8") as f:
            m = json.load(f)
    except (OSError, ValueError) as e:
        raise InvalidArgumentError(f"{folder} holds no readable tile set manifest ({e})") from None
    if m.get("format") != "fracterra-tileset":
        raise InvalidArgumentError(f"{path} is not a fracterra tile set manifest")
    return m


def extent(folder, lod=0):
    """(width, height): the whole set's samples per side at level of detail `lod`."""
    lib = library()
    w, h = c_int64(), c_int64()
    lib.check(lib.ft_tileset_extent(os.fsencode(str(folder)), lod, byref(w), byref(h)))
    return w.value, h.value


def read_window(folder, lod=0, x0=0, y0=0, width=None, height=None):
    """A Heightfield (close it) of the window [x0, x0 + width) x [y0, y0 + height), counted at
    level of detail `lod` (every 2^lod-th sample), read back from the tile files it touches, in
    the set's real heights; None width/height: to the end of the set."""
    lib = library()
    ew, eh = extent(folder, lod)
    width = ew - x0 if width is None else width
    height = eh - y0 if height is None else height
    out = c_void_p()
    lib.check(lib.ft_tileset_read_window(os.fsencode(str(folder)), lod, x0, y0, width, height, byref(out)))
    return Heightfield(out)


def read_map_window(folder, name, lod=0, x0=0, y0=0, width=None, height=None):
    """A Heightfield (close it) of map `name` (one of core.erosion.MAPS) of a set with maps, as read_window."""
    if name not in MAPS:
        raise InvalidArgumentError(f"a tile set's maps are {', '.join(MAPS)}; got {name!r}")
    lib = library()
    ew, eh = extent(folder, lod)
    width = ew - x0 if width is None else width
    height = eh - y0 if height is None else height
    out = c_void_p()
    lib.check(lib.ft_tileset_read_map_window(os.fsencode(str(folder)), MAPS.index(name), lod, x0, y0, width, height,
                                             byref(out)))
    return Heightfield(out)


def window_colors(folder, rules, lod, x0, y0, width, height):
    """Linear RGBA (a (width * height * 4,) float32 numpy array, rows from the north) of splat rules
    `rules` (core.splat's) over a window of a finished set, as the whole's colours: the set's height
    range and area, its maps' deposits and flow, slopes across the window's edges."""
    import numpy as np
    lib = library()
    out = np.empty(width * height * 4, dtype=np.float32)
    lib.check(lib.ft_tileset_window_colors(os.fsencode(str(folder)), lod, x0, y0, width, height, rules.layers,
                                           rules.count, out.ctypes.data_as(ctypes.POINTER(ctypes.c_float)),
                                           out.size))
    return out


def cut_for_engine(folder, engine, out_dir, side=0, region_size=256):
    """Cuts the finished set in `folder` for a game engine ("unity", "unreal", "godot") into `out_dir`, with
    OUT_DIR/ENGINE.json (and an eroded set's splat maps), as `fracterra tiles --engine` does."""
    lib = library()
    lib.check(lib.ft_tileset_cut_for_engine(os.fsencode(str(folder)), engine.encode(), side, region_size,
                                            os.fsencode(str(out_dir))))


def _hurst_params(method):
    lib = library()
    hp = lib.hurst_params_type()
    lib.check(lib.ft_hurst_params_init(byref(hp)))
    if method not in HURST_METHODS:
        raise InvalidArgumentError(f"the set's H needs an aligned method ({', '.join(HURST_METHODS)}), got {method!r}")
    hp.method = HURST_METHODS[method]
    return hp


def terrain_extent(settings, reference):
    lib = library()
    p, _keep = _terrain(settings, reference)
    w, h = c_int64(), c_int64()
    lib.check(lib.ft_terrain_extent(byref(p), 0, byref(w), byref(h)))
    return w.value, h.value


def tile_increment_sums(col, row, settings, reference, tile, method):
    """One task: the increment sums of tile (col, row), generated as a window (exact floats)."""
    lib = library()
    p, _keep = _terrain(settings, reference)
    w, h = terrain_extent(settings, reference)
    x0, y0 = col * tile, row * tile
    tw, th = min(tile + 1, w - x0), min(tile + 1, h - y0)
    hp = _hurst_params(method)
    n = c_size_t()
    lib.check(lib.ft_increment_lags(byref(hp), w, h, None, 0, byref(n)))
    sums, counts = (c_double * n.value)(), (c_double * n.value)()
    out = c_void_p()
    lib.check(lib.ft_terrain_generate_window(byref(p), x0, y0, tw, th, byref(out)))
    with Heightfield(out) as window:
        lib.check(lib.ft_increment_sums(window.handle, byref(hp), x0, y0, w, h, sums, counts, n.value))
    return list(sums), list(counts)


def hurst_from_sums(settings, sums, counts, method="variogram_aligned", reference=None):
    """H, D and the fit of the whole surface from its reduced increment sums."""
    lib = library()
    w, h = terrain_extent(settings, reference)
    hp = _hurst_params(method)
    n = len(sums)
    r = HurstResult()
    r.struct_size = ctypes.sizeof(HurstResult)
    lib.check(lib.ft_hurst_from_increment_sums(byref(hp), w, h, (c_double * n)(*sums), (c_double * n)(*counts), n,
                                               byref(r)))
    return {"hurst": r.hurst, "dimension": r.dimension, "std_error": r.std_error, "lag_min": r.band_lo,
            "lag_max": r.band_hi, "points": r.points, "method": method}
