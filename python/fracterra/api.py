# SPDX-License-Identifier: GPL-3.0-or-later
"""The numpy API: terrain(), erode(), analyze(), splat(), save(), load().

Everything goes through the add-on's ctypes binding (fracterra.core, the same
files the Blender add-on carries). The keyword arguments of terrain() and
erode() are the rows of the library's parameter tables, so their names,
defaults, ranges and docs are the library's; help(fracterra.terrain) lists
them.
"""

from __future__ import annotations

import ctypes
import inspect
import os
from ctypes import POINTER, byref, c_float, c_int32, c_uint16, c_void_p
from typing import Any, Optional, Union

import numpy as np

from .core.binding import library
from .core.errors import InvalidArgumentError
from .core.erosion import erode_struct
from .core.errors import LibraryNotFoundError
from .core.polylines import hurst_of_heightfield
from .core.raster import read_heightfield, write_heightfield
from .core.splat import default_rules
from .core.terrain import Heightfield, generate_from_struct

PathLike = Union[str, os.PathLike]


class Terrain(np.ndarray):
    """float32 heights, row-major (row index = y), with `world_size`: the extent
    along x in world units (0 when unknown). Any numpy operation keeps it."""

    world_size: float

    def __new__(cls, data, world_size: float = 0.0):
        obj = np.ascontiguousarray(data, dtype=np.float32).view(cls)
        obj.world_size = float(world_size)
        return obj

    def __array_finalize__(self, obj):
        self.world_size = float(getattr(obj, "world_size", 0.0))


# --- the parameter tables as keyword arguments --------------------------------

_FLAG_STRUCT_SIZE, _FLAG_DATA, _FLAG_MIN_EXCLUSIVE, _FLAG_MAX_EXCLUSIVE = 1, 2, 4, 8
_PY_TYPES = {"uint32": int, "int32": int, "int64": int, "uint64": int, "float": float, "double": float,
             "bool": bool, "enum": str}


def _settings(kind: str) -> list:
    """The rows of table `kind` a caller sets by keyword (not struct_size, data or pointers)."""
    return [r for r in library().param_rows[kind]
            if not r["flags"] & (_FLAG_STRUCT_SIZE | _FLAG_DATA) and r["type"] in _PY_TYPES]


def _set_fields(struct, kind: str, values: dict, skip=()) -> None:
    rows = {r["name"]: r for r in _settings(kind) if r["name"] not in skip}
    for name, value in values.items():
        row = rows.get(name)
        if row is None:
            raise TypeError(f"unknown setting {name!r}; the settings are: {', '.join(rows)}")
        if row["type"] == "enum":
            items = {ident.lower(): v for ident, _label, _doc, v in row["items"]}
            if isinstance(value, str):
                if value.lower() not in items:
                    raise InvalidArgumentError(f"{name} must be one of {', '.join(items)}, got {value!r}")
                value = items[value.lower()]
        elif row["type"] == "bool":
            value = 1 if value else 0
        if row["count"] > 1:
            getattr(struct, name)[:] = list(value)
        else:
            setattr(struct, name, value)


def _default_text(row) -> str:
    if row["type"] == "enum":
        return next(ident.lower() for ident, _l, _d, v in row["items"] if v == int(row["default_value"]))
    if row["type"] == "bool":
        return str(bool(row["default_value"]))
    if _PY_TYPES[row["type"]] is int:
        return str(int(row["default_value"]))
    return f"{row['default_value']:g}"


def _range_text(row) -> str:
    if row["type"] == "enum":
        return "one of " + ", ".join(ident.lower() for ident, _l, _d, _v in row["items"])
    if row["type"] == "bool":
        return "True or False"
    lo, hi = row["hard_min"], row["hard_max"]
    left = "(" if row["flags"] & _FLAG_MIN_EXCLUSIVE else "["
    right = ")" if row["flags"] & _FLAG_MAX_EXCLUSIVE else "]"
    return f"{left}{lo:g}, {hi:g}{right}" + (f" {row['unit']}" if row["unit"] else "")


def _document(fn, kind: str, leading: list, skip=()) -> None:
    """Gives `fn` the signature and docstring of its leading parameters plus
    every setting of table `kind` (keyword-only, default None = the library's)."""
    params = list(leading)
    lines = [inspect.getdoc(fn) or "", "", f"Settings (the library's ft_{kind} table; None keeps its default):"]
    for row in _settings(kind):
        if row["name"] in skip:
            continue
        hint = _PY_TYPES[row["type"]]
        params.append(inspect.Parameter(row["name"], inspect.Parameter.KEYWORD_ONLY, default=None,
                                        annotation=Optional[hint]))
        lines.append(f"    {row['name']}: {row['label']}. {row['doc']}. Default {_default_text(row)}, "
                     f"range {_range_text(row)}.")
    fn.__signature__ = inspect.Signature(params, return_annotation=inspect.signature(fn).return_annotation)
    fn.__doc__ = "\n".join(lines)


# --- heightfields between numpy and the library -------------------------------

def _to_library(z) -> Heightfield:
    lib = library()
    a = np.ascontiguousarray(z, dtype=np.float32)
    if a.ndim != 2:
        raise InvalidArgumentError(f"a terrain is a 2-D array of heights, got {a.ndim} dimensions")
    out = c_void_p()
    lib.check(lib.ft_heightfield_create(a.shape[1], a.shape[0], a.ctypes.data_as(POINTER(c_float)), byref(out)))
    hf = Heightfield(out)
    ws = float(getattr(z, "world_size", 0.0) or 0.0)
    if ws > 0:
        lib.check(lib.ft_heightfield_set_world_size(hf.handle, ws))
    return hf


def _from_library(hf: Heightfield) -> Terrain:
    a = np.frombuffer(hf.to_array(), dtype=np.float32).reshape(hf.height, hf.width)
    return Terrain(a, hf.world_size)


def _strip_none(kw: dict) -> dict:
    return {k: v for k, v in kw.items() if v is not None}


# --- the API ------------------------------------------------------------------

def terrain(*, threads: int = 0, progress=None, **settings) -> Terrain:
    """A fractal terrain as a Terrain (numpy float32, world_size attached).

    threads: worker threads, 0 for all cores (the result never depends on it).
    progress: None or callable(fraction) returning True to cancel (raises CancelledError).
    """
    lib = library()
    p = lib.terrain_params_type()
    lib.check(lib.ft_terrain_params_init(byref(p)))
    _set_fields(p, "terrain", _strip_none(settings), skip=("threads",))
    p.threads = threads
    with generate_from_struct(p, progress) as hf:
        return _from_library(hf)


def erode(z, preset: Optional[str] = None, *, maps: bool = True, threads: int = 0, progress=None,
          **settings) -> tuple:
    """Erodes `z` (a Terrain or 2-D array; its world_size, else 10): returns
    (eroded Terrain, {map name: Terrain}) with the maps drainage_area, slope,
    curvature, water_depth, eroded and deposited (empty with maps=False).

    preset: an erosion preset (gentle_valleys, rugged_mountains, badlands,
    alluvial_fans, scree_slopes, or their old names valleys, land, rain, scree);
    the settings given override its values, as on the command line.
    """
    lib = library()
    with _to_library(z) as hf:
        if hf.world_size <= 0:
            lib.check(lib.ft_heightfield_set_world_size(hf.handle, 10.0))
        p = lib.erosion_params_type()
        if preset:
            lib.check(lib.ft_erosion_preset_fitted(preset.lower().encode(), hf.handle, byref(p)))
        else:
            lib.check(lib.ft_erosion_params_init(byref(p)))
        _set_fields(p, "erosion", _strip_none(settings), skip=("threads",))
        p.threads = threads
        eroded, made = erode_struct(hf, p, progress, maps)
        arrays = {}
        for name, m in made.items():
            with m:
                arrays[name] = _from_library(m)
        with eroded:
            return _from_library(eroded), arrays


def analyze(z, method: str = "auto", *, drainage: bool = True, periodic: bool = False,
            min_area_cells: float = 20.0) -> dict:
    """Measures `z`: {'hurst', 'dimension', 'std_error', 'estimator', 'reason',
    'band_lo', 'band_hi', 'points', 'min', 'max', 'mean', 'std'} and, with
    drainage=True, 'drainage': {'hack_h', 'hack_h_stderr', 'theta',
    'theta_stderr', 'hack_bins', 'theta_bins'} (Hack's law and the slope-area
    concavity over channels of at least min_area_cells cells; cells of filled
    lakes count in neither, and theta is fitted from the slope-area turnover up).

    method: auto (the library's choice for the grid, as `fracterra analyze`),
    variogram, variogram_aligned, madogram_aligned or spectral.
    """
    lib = library()
    with _to_library(z) as hf:
        out = hurst_of_heightfield(hf, method.upper())
        out.pop("struct_size", None)
        out.pop("auto_reason_text", None)
        out.update(hf.stats())
        if drainage:
            from .core.binding import DrainageStats
            d = DrainageStats()
            lib.check(lib.ft_drainage_statistics(hf.handle, 1 if periodic else 0, float(min_area_cells), byref(d)))
            out["drainage"] = {name: getattr(d, name) for name, _ in DrainageStats._fields_}
        return out


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
        _set_fields(layer, "splat", rule)
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
        hf = _to_library(z)
        handles.append(hf)
        extra = []
        for name in ("deposited", "drainage_area"):
            m = (maps or {}).get(name)
            if m is None:
                extra.append(None)
                continue
            handles.append(_to_library(m))
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
    .npy, .tif COG, .exr, .raw/.r16), atomically, with its world size."""
    with _to_library(z) as hf:
        write_heightfield(hf, path)


def load(path: PathLike) -> Terrain:
    """Reads a heightfield (any format `fracterra` reads: PNG, PGM, NPY, EXR,
    RAW16, GeoTIFF and what GDAL reads) as a Terrain in its real units."""
    with read_heightfield(path) as hf:
        return _from_library(hf)


def version() -> str:
    """The loaded library's version and ABI, e.g. 'libfracterra 0.3.0 (ABI 2.19)'."""
    lib = library()
    return f"libfracterra {lib.version} (ABI {lib.abi_major}.{lib.abi_minor})"


def _annotate() -> None:
    threads = inspect.Parameter("threads", inspect.Parameter.KEYWORD_ONLY, default=0, annotation=int)
    progress = inspect.Parameter("progress", inspect.Parameter.KEYWORD_ONLY, default=None)
    _document(terrain, "terrain", [threads, progress], skip=("threads",))
    pos = inspect.Parameter.POSITIONAL_OR_KEYWORD
    _document(erode, "erosion",
              [inspect.Parameter("z", pos, annotation=Any),
               inspect.Parameter("preset", pos, default=None, annotation=Optional[str]),
               inspect.Parameter("maps", inspect.Parameter.KEYWORD_ONLY, default=True, annotation=bool),
               threads, progress], skip=("threads",))


try:
    _annotate()
except LibraryNotFoundError:  # the calls will say why; help() then shows the plain docs
    pass
