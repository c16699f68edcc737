# SPDX-License-Identifier: GPL-3.0-or-later
"""The numpy API beside the pipeline (pipeline.py: terrain, erode, rivers):
analyze(), splat(), save(), load(), version().

Everything goes through the add-on's ctypes binding (fracterra.core, the same
files the Blender add-on carries)."""

from __future__ import annotations

import os
from ctypes import POINTER, byref, c_float, c_uint16
from typing import Optional, Union

import numpy as np

from .arrays import Terrain, from_library, to_library, world_of, world_size_or_default
from .core.binding import library
from .core.polylines import hurst_of_heightfield
from .core.raster import read_heightfield, write_heightfield
from .core.splat import default_rules
from .keywords import Table

PathLike = Union[str, os.PathLike]


def analyze(z, method: str = "auto", *, drainage: bool = True, periodic: Optional[bool] = None,
            min_area_cells: float = 20.0, points: bool = False, rivers: bool = False) -> dict:
    """Measures a terrain or a polyline set.

    A terrain `z`: {'hurst', 'dimension', 'std_error', 'estimator', 'reason',
    'band_lo', 'band_hi', 'points', 'min', 'max', 'mean', 'std'}; with
    drainage=True, 'drainage': {'hack_h', 'hack_h_stderr', 'theta',
    'theta_stderr', 'hack_bins', 'theta_bins'} (Hack's law and the slope-area
    concavity over channels of at least min_area_cells cells; cells of filled
    lakes count in neither, and theta is fitted from the slope-area turnover
    up); with points=True, 'fit': {'x', 'y'}, the points the estimate fitted
    (lags and the variogram or madogram; with method='spectral', frequencies in
    cycles per record and the rows' and columns' averaged periodogram, ~ f^-(2H + 1)); with
    rivers=True, 'rivers': ft.rivers(z).measures() (Horton's ratios, drainage
    density, Hack's h of the network).
    method: auto (the library's choice for the grid, as `fracterra analyze`),
    variogram, variogram_aligned, madogram_aligned or spectral.
    periodic: route the drainage on a torus; None: as z tiles (a Terrain's
    period_overlap: its repeated last row and column are left out).

    A fracterra.Lines (ft.polyline()'s): seed 003's measures, as
    ft.polylines.measure: eta, chi, gamma, mass and box-counting dimensions.
    """
    from .polylines import Lines, measure
    if isinstance(z, Lines):
        return measure(z)
    lib = library()
    with to_library(z) as hf:
        out = hurst_of_heightfield(hf, method.upper())
        out.pop("struct_size", None)
        out.pop("auto_reason_text", None)
        out.update(hf.stats())
        if points:
            out["fit"] = _fit_points(hf, method)
    if drainage:
        from .core.binding import DrainageStats
        _ws, overlap, _sea = world_of(z)
        if periodic is None:
            periodic = overlap >= 0
        a = np.asarray(z)
        ws = world_size_or_default(z)
        if periodic and overlap > 0:  # the torus of its true period, as the pipeline routes it
            a = a[:-overlap, :-overlap]
            ws = ws * (a.shape[1] - 1) / (np.asarray(z).shape[1] - 1)
        d = DrainageStats()
        with to_library(a, world_size=ws) as hf:
            lib.check(lib.ft_drainage_statistics(hf.handle, 1 if periodic else 0, float(min_area_cells), byref(d)))
        out["drainage"] = {name: getattr(d, name) for name, _ in DrainageStats._fields_}
    if rivers:
        from .pipeline import rivers as trace
        out["rivers"] = trace(z).measures()
    return out


def _fit_points(hf, method) -> dict:
    from ctypes import c_double, c_int64, sizeof
    from .core.binding import HurstResult, enum_values
    lib = library()
    p = lib.hurst_params_type()
    lib.check(lib.ft_hurst_params_init(byref(p)))
    p.method = enum_values("hurst", "method")[method.upper()]
    r = HurstResult(struct_size=sizeof(HurstResult))
    n = c_int64()
    lib.check(lib.ft_hurst_heightfield_points(hf.handle, byref(p), byref(r), None, None, 0, byref(n)))
    x, y = np.empty(n.value), np.empty(n.value)
    lib.check(lib.ft_hurst_heightfield_points(hf.handle, byref(p), byref(r), x.ctypes.data_as(POINTER(c_double)),
                                              y.ctypes.data_as(POINTER(c_double)), n.value, byref(n)))
    return {"x": x, "y": y}


def _layers(rules) -> tuple:
    """(array of ft_splat_params, the bytes objects their names point to)."""
    lib = library()
    if rules is None:
        built_in = default_rules()
        return built_in.layers, built_in.keep
    arr = (lib.splat_params_type * len(rules))()
    keep = []
    for layer, rule in zip(arr, rules):
        lib.check(lib.ft_splat_params_init(byref(layer)))
        rule = dict(rule)
        name = rule.pop("name", None)
        if name is not None:
            keep.append(str(name).encode())
            layer.name = keep[-1]
        Table("splat").fill(layer, rule)
    return arr, keep


def splat(z, maps: Optional[dict] = None, rules: Optional[list] = None, total: int = 255,
          color: bool = False) -> np.ndarray:
    """Splat (weight) maps of `z` by layer rules, as `fracterra splat` writes them:
    a uint16 array (height, width, layers) whose layers sum to exactly `total`
    (255 or 65535) at every sample; with color=True instead an RGB float32
    colour map (height, width, 3). maps: erode()'s maps (deposited and
    drainage_area feed the sediment rule) or None. rules: None for the built-in
    grass, rock, sediment, snow, or a list of dicts with the fields of
    ft_splat_params (name, height_min, slope_min, ..., color)."""
    lib = library()
    layers, _names = _layers(rules)
    handles = []
    try:
        hf = to_library(z, world_size=world_size_or_default(z))
        handles.append(hf)
        extra = []
        for name in ("deposited", "drainage_area"):
            m = (maps or {}).get(name)
            if m is None:
                extra.append(None)
                continue
            handles.append(to_library(m))
            extra.append(handles[-1].handle)
        h, w, n = hf.height, hf.width, len(layers)
        if color:
            out = np.empty((h, w, 3), dtype=np.float32)
            lib.check(lib.ft_splat_colors(hf.handle, extra[0], extra[1], layers, n,
                                          out.ctypes.data_as(POINTER(c_float)), out.size))
        else:
            out = np.empty((h, w, n), dtype=np.uint16)
            lib.check(lib.ft_splat_weights(hf.handle, extra[0], extra[1], layers, n, int(total),
                                           out.ctypes.data_as(POINTER(c_uint16)), out.size))
        return out
    finally:
        for handle in handles:
            handle.close()


def save(z, path: PathLike) -> None:
    """Writes `z` to `path` in the format of its extension (.png 16-bit, .pgm,
    .npy with its sidecar .npy.json, .tif COG, .exr, .raw/.r16 with .raw.json),
    atomically, with its world size (every format records it)."""
    with to_library(z, allow_nan=os.fspath(path).lower().endswith(".npy")) as hf:
        write_heightfield(hf, path)


def load(path: PathLike) -> Terrain:
    """Reads a heightfield (any format `fracterra` reads: PNG, PGM, NPY, EXR,
    RAW16, GeoTIFF and what GDAL reads) as a Terrain in its real units, with
    the world size the file records (0 when it records none)."""
    with read_heightfield(path) as hf:
        return from_library(hf)


def version() -> str:
    """The loaded library's version and ABI, e.g. 'libfracterra 0.6.0 (ABI 2.27)'."""
    lib = library()
    return f"libfracterra {lib.version} (ABI {lib.abi_major}.{lib.abi_minor})"


__all__ = ["Terrain", "analyze", "splat", "save", "load", "version"]
