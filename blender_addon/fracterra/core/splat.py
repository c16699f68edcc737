# SPDX-License-Identifier: GPL-3.0-or-later
"""Splat layer rules and the colour map they give (fracterra/splat.h): the one
rule that colours a terrain in Blender (its material reads the colours as a
point attribute), in the POV-Ray export (the same colours as a PNG) and in the
game-engine maps of `fracterra splat`. The rules are the library's: the
built-in set, a rules JSON file the library reads and checks, or dicts of
ft_splat_params' fields (fracterra.splat, which builds a Rules of them)."""

import ctypes
import os
from ctypes import POINTER, byref, c_float, c_int32, c_void_p

import numpy as np

from .binding import library
from .terrain import _ProgressBridge


class Rules:
    """An array of ft_splat_params and what their names point to (kept alive
    with it): pass `layers` and `count` to the library."""

    def __init__(self, layers, keep=()):
        self.layers, self.keep = layers, list(keep)

    @property
    def count(self):
        return len(self.layers)

    @property
    def names(self):
        return [layer.name.decode() if layer.name else "" for layer in self.layers]


def _fetched(fill):
    """Rules from a library call fill(layers or None, capacity, byref(count)), the
    names copied out (they point into storage the caller may release next)."""
    lib = library()
    layer_type = lib.splat_params_type
    count = c_int32()
    lib.check(fill(None, 0, byref(count)))
    layers = (layer_type * count.value)()
    for layer in layers:
        layer.struct_size = ctypes.sizeof(layer_type)
    lib.check(fill(layers, count.value, byref(count)))
    keep = []
    for layer in layers:
        if layer.name is not None:
            keep.append(bytes(layer.name))
            layer.name = keep[-1]
    return Rules(layers, keep)


def default_rules():
    """The built-in grass, rock, sediment and snow (ft_splat_default_layers)."""
    return _fetched(library().ft_splat_default_layers)


def read_rules(path):
    """The rules of a JSON file, read and checked by the library as `fracterra
    splat --rules` reads them; a bad file raises FracterraError with the
    library's message (the file, layer and field named)."""
    lib = library()
    handle = c_void_p()
    lib.check(lib.ft_splat_rules_read(os.fsencode(path), byref(handle)))
    try:
        return _fetched(lambda layers, capacity, count: lib.ft_splat_rules_layers(handle, layers, capacity, count))
    finally:
        lib.ft_splat_rules_free(handle)


def rules_for(path):
    """The rules an artist chose: a rules file (blank: the built-in set)."""
    return read_rules(path) if path else default_rules()


def colors(terrain, rules=None, deposited=None, drainage_area=None):
    """The colour map of library heightfield `terrain` by `rules` (default: the
    built-in set), sRGB 0..1 as an (n, 3) float32 array in the samples' order.
    deposited, drainage_area: library heightfields of the erosion maps (world
    units) or None (their conditions then see none). The slope is the
    terrain's own in its world size (ft_heightfield_world_size)."""
    lib = library()
    rules = rules if rules is not None else default_rules()
    out = np.empty((terrain.width * terrain.height, 3), dtype=np.float32)
    lib.check(lib.ft_splat_colors(terrain.handle, deposited.handle if deposited else None,
                                  drainage_area.handle if drainage_area else None, rules.layers, rules.count,
                                  out.ctypes.data_as(POINTER(c_float)), out.size))
    return out


def linear_rgba(terrain, rules=None, deposited=None, drainage_area=None, threads=0, progress=None):
    """colors() decoded to linear RGB by the library, with alpha 1: an (n * 4,)
    float32 array in the samples' order, as Blender's colour attributes take
    it (ft_splat_colors_linear_rgba, ABI 2.25). threads: 0 for all cores.
    progress: None or callable(fraction) -> True to cancel (raises
    CancelledError)."""
    lib = library()
    rules = rules if rules is not None else default_rules()
    out = np.empty(terrain.width * terrain.height * 4, dtype=np.float32)
    bridge = _ProgressBridge(progress)
    status = lib.ft_splat_colors_linear_rgba(terrain.handle, deposited.handle if deposited else None,
                                             drainage_area.handle if drainage_area else None, rules.layers,
                                             rules.count, threads, bridge.c_fn, None,
                                             out.ctypes.data_as(POINTER(c_float)), out.size)
    bridge.reraise()
    lib.check(status)
    return out


def linear_from_srgb(c):
    """sRGB 0..1 -> linear RGB (IEC 61966-2-1), float32: Blender's colour
    attributes and the POV-Ray export's colours are linear."""
    # In float32, in place: 3.5x faster than float64 (2049^2 x 3 values:
    # 0.32 s against 1.1 s under load 10), within 2.4e-7 of it.
    c = np.asarray(c, dtype=np.float32)
    out = (c + np.float32(0.055)) / np.float32(1.055)
    np.power(out, np.float32(2.4), out=out)
    low = c <= np.float32(0.04045)
    out[low] = c[low] / np.float32(12.92)
    return out

