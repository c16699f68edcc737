# SPDX-License-Identifier: GPL-3.0-or-later
"""numpy arrays in and out of the library: the Terrain type (heights with
their world) and the checks every array from a caller passes before any
pointer to it reaches C, so that bad input is an exception naming what is
allowed, never a crash or a silent wrong answer."""

from __future__ import annotations

import math
import sys
from ctypes import POINTER, byref, c_float, c_void_p

import numpy as np

from .core.binding import library
from .core.errors import InvalidArgumentError
from .core.terrain import Heightfield

# The world size the CLI and the library take for a terrain that records none
# (ft_terrain_params.world_size's default).
DEFAULT_WORLD_SIZE = 10.0


class Terrain(np.ndarray):
    """float32 heights, row-major (row index = y), with their world:

    world_size: the extent along x in world units (0: unknown; the functions
    that need one then take 10 and say so on stderr).
    period_overlap: -1 when it does not tile; else it tiles, and its last
    `period_overlap` rows and columns repeat the first (midpoint and additions
    terrains: 1). `periodic` is period_overlap >= 0.
    sea_level: the height of its own flat sea (a landform's), NaN for none.

    ft.terrain() sets them; ft.erode(), ft.rivers(), ft.analyze() and the
    others read them, so a terrain kept in numpy continues the pipeline as
    ft.terrain(erode=...) would. Slicing keeps world_size (the extent the
    samples span is the caller's to change) but a slice of another shape no
    longer tiles."""

    world_size: float
    period_overlap: int
    sea_level: float

    def __new__(cls, data, world_size: float = 0.0, period_overlap: int = -1, sea_level: float = math.nan):
        obj = np.ascontiguousarray(data, dtype=np.float32).view(cls)
        obj.world_size = float(world_size)
        obj.period_overlap = int(period_overlap)
        obj.sea_level = float(sea_level)
        return obj

    def __array_finalize__(self, obj):
        self.world_size = float(getattr(obj, "world_size", 0.0))
        same_grid = obj is not None and getattr(obj, "shape", None) == self.shape
        self.period_overlap = int(getattr(obj, "period_overlap", -1)) if same_grid else -1
        self.sea_level = float(getattr(obj, "sea_level", math.nan))

    @property
    def periodic(self) -> bool:
        return self.period_overlap >= 0

    def __reduce__(self):  # pickling (Dask, multiprocessing) keeps the world
        rebuild, args, state = super().__reduce__()
        return rebuild, args, (state, self.world_size, self.period_overlap, self.sea_level)

    def __setstate__(self, state):
        base, self.world_size, self.period_overlap, self.sea_level = state
        super().__setstate__(base)


def world_of(z) -> tuple:
    """(world_size, period_overlap, sea_level) of a Terrain, or of a plain array (0, -1, NaN)."""
    return (float(getattr(z, "world_size", 0.0) or 0.0), int(getattr(z, "period_overlap", -1)),
            float(getattr(z, "sea_level", math.nan)))


def world_size_or_default(z, what: str = "the terrain") -> float:
    """z's world size, or the default with a one-line warning on stderr (as the CLI's)."""
    ws = world_of(z)[0]
    if ws > 0:
        return ws
    print(f"fracterra: warning: {what} records no world size (a plain array, or a file without one); "
          f"using the default, {DEFAULT_WORLD_SIZE:g} world units (set its .world_size)", file=sys.stderr)
    return DEFAULT_WORLD_SIZE


def grid(z, what: str = "a terrain", allow_nan: bool = False, lo=None, hi=None) -> np.ndarray:
    """z as a C-contiguous float32 2-D array, checked: a real-valued dtype
    (floats, integers, bool), two dimensions, at least one sample, finite
    (unless allow_nan), within [lo, hi] when given. Non-contiguous and
    Fortran-ordered arrays are copied (numpy's views, such as z.T or
    z[::2, ::2], are ordinary input); nothing else is guessed."""
    if isinstance(z, (str, bytes, dict)) or z is None:
        raise TypeError(f"{what} is a 2-D numpy array (or anything np.asarray takes), got {type(z).__name__}")
    a = np.asarray(z)
    if a.dtype.kind not in "fiub":
        raise TypeError(f"{what} must hold real numbers (a float or integer dtype), got dtype {a.dtype}")
    if a.ndim != 2:
        raise InvalidArgumentError(f"{what} must be a 2-D array (rows, columns), got {a.ndim} dimension"
                                   f"{'' if a.ndim == 1 else 's'} of shape {a.shape}")
    if a.size == 0:
        raise InvalidArgumentError(f"{what} must hold at least 1 x 1 samples, got shape {a.shape}")
    if max(a.shape) >= 2 ** 31:
        raise InvalidArgumentError(f"{what} has shape {a.shape}; the library takes at most 2^31 - 1 per side")
    a = np.ascontiguousarray(a, dtype=np.float32)
    if not allow_nan:
        bad = ~np.isfinite(a)
        if bad.any():
            row, col = (int(v) for v in np.argwhere(bad)[0])
            raise InvalidArgumentError(f"{what} must be finite: it holds {int(bad.sum())} NaN or infinite "
                                       f"samples, the first at row {row}, column {col}")
    if lo is not None and hi is not None and (a.min() < lo or a.max() > hi):
        raise InvalidArgumentError(f"{what} must hold values in [{lo:g}, {hi:g}], got "
                                   f"[{float(a.min()):g}, {float(a.max()):g}]")
    return a


def to_library(z, what: str = "a terrain", allow_nan: bool = False, world_size=None) -> Heightfield:
    """A library heightfield holding z's samples and world size (world_size
    given: that one instead)."""
    lib = library()
    a = grid(z, what, allow_nan)
    out = c_void_p()
    lib.check(lib.ft_heightfield_create(a.shape[1], a.shape[0], a.ctypes.data_as(POINTER(c_float)), byref(out)))
    hf = Heightfield(out)
    ws = world_of(z)[0] if world_size is None else float(world_size)
    if ws > 0:
        lib.check(lib.ft_heightfield_set_world_size(hf.handle, ws))
    return hf


def from_library(hf: Heightfield, period_overlap: int = -1, sea_level: float = math.nan) -> Terrain:
    """A library heightfield as a Terrain (a copy: the handle may be closed after)."""
    a = np.frombuffer(hf.to_array(), dtype=np.float32).reshape(hf.height, hf.width)
    return Terrain(a, hf.world_size, period_overlap, sea_level)


def mask_of(m, what: str):
    """A mask or map in [0, 1] as (width, height, float32 array) for core.terrain.attach_map."""
    a = grid(m, what, lo=0.0, hi=1.0)
    return a.shape[1], a.shape[0], a


__all__ = ["Terrain", "DEFAULT_WORLD_SIZE", "world_of", "world_size_or_default", "grid", "to_library",
           "from_library", "mask_of"]
