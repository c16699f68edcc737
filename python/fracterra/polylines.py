# SPDX-License-Identifier: GPL-3.0-or-later
"""Fractal polylines as vertex arrays (fracterra/polyline.h): Nikulin's FPL in
2D and 3D (lightning with branches), Koch, dragon, Sierpinski, IFS, the Voss
profile; their measures (eta, chi, gamma, mass and box dimensions); the FPL
ensemble study of seed 003; a terrain's coastline."""

from __future__ import annotations

import ctypes
import math
from ctypes import POINTER, byref, c_double, c_int32, c_void_p
from typing import Any

import numpy as np

from .arrays import to_library
from .core.binding import FplStudyRow, library
from .core.errors import InvalidArgumentError
from .core.polylines import Polylines, run_polyline
from .core.terrain import _ProgressBridge
from .keywords import Table, document, split

_RNGS = {"uniform": 0, "normal": 1}


class Lines:
    """Polylines sharing one vertex array: xyz (n, 3) float64, radii (n,)
    float64, offsets (lines + 1,) int64 (line k is xyz[offsets[k]:offsets[k + 1]]).
    Line 0 is the main line (through the base's nodes); the others are its
    branches. lines() lists them as (m, 3) arrays; main and branches too."""

    def __init__(self, xyz, radii=None, offsets=None):
        self.xyz = np.ascontiguousarray(xyz, dtype=np.float64).reshape(-1, 3)
        n = len(self.xyz)
        self.radii = np.zeros(n) if radii is None else np.ascontiguousarray(radii, dtype=np.float64)
        self.offsets = np.array([0, n], np.int64) if offsets is None else np.ascontiguousarray(offsets, dtype=np.int64)
        if self.radii.shape != (n,):
            raise InvalidArgumentError(f"radii must hold one value per vertex ({n}), got shape {self.radii.shape}")
        o = self.offsets
        if o.ndim != 1 or len(o) < 2 or o[0] != 0 or o[-1] != n or np.any(np.diff(o) < 0):
            raise InvalidArgumentError(f"offsets must rise from 0 to the vertex count {n}, got {o[:8]}...")
        if not np.all(np.isfinite(self.xyz)):
            raise InvalidArgumentError("the vertices must be finite")

    @classmethod
    def _from_handle(cls, pl: Polylines) -> "Lines":
        with pl:
            return cls(np.asarray(pl.xyz()), np.asarray(pl.radii()), np.asarray(pl.offsets()))

    def _handle(self) -> Polylines:
        return Polylines.from_arrays(self.xyz.ravel(), self.radii, self.offsets)

    @property
    def line_count(self) -> int:
        return len(self.offsets) - 1

    def lines(self) -> list:
        return [self.xyz[self.offsets[k]:self.offsets[k + 1]] for k in range(self.line_count)]

    @property
    def main(self) -> np.ndarray:
        return self.xyz[self.offsets[0]:self.offsets[1]]

    @property
    def branches(self) -> list:
        return self.lines()[1:]

    def __len__(self):
        return self.line_count

    def __repr__(self):
        return f"<fracterra.Lines: {self.line_count} lines, {len(self.xyz)} vertices>"


def polyline(method: str = "fpl", *, base=None, plane_normal=None, threads: int = 0, progress=None,
             **settings) -> Lines:
    """A fractal polyline (ft_polyline_generate) as `fracterra polyline` makes it.

    method: fpl, fpl3d, koch, dragon, sierpinski, ifs, profile (the table's
    names, as the CLI takes them). base: None (the unit segment (0,0,0) ->
    (1,0,0)) or an (n, 3) array of n >= 2 nodes the main line passes through.
    plane_normal: (x, y, z) of the 2D methods' plane. Returns Lines: line 0 the
    main line, then its branches (branch_prob > 0); IFS gives one line per point.
    """
    lib = library()
    table = Table("polyline", skip=("threads",))
    given = split(settings, {"polyline": table}, ("method", "base", "plane_normal", "threads", "progress"))
    p = lib.polyline_params_type()
    lib.check(lib.ft_polyline_params_init(byref(p)))
    table.fill(p, {"method": method, **given["polyline"]})
    b = None
    if base is not None:
        b = np.array(base, dtype=np.float64)  # a writable copy: the library reads it through a buffer
        if b.ndim != 2 or b.shape[1] != 3 or len(b) < 2 or not np.all(np.isfinite(b)):
            raise InvalidArgumentError(f"base must be an (n, 3) array of n >= 2 finite nodes, got shape {b.shape}")
    return Lines._from_handle(run_polyline(lib, p, b, plane_normal, progress, threads))


def measure(lines: Lines) -> dict:
    """Seed 003's measures of a polyline set: eta, chi, gamma and the mass
    dimension of line 0 against its chord, the total length, and the
    box-counting dimension of all lines in the x,y plane (NaN where they
    cannot be measured)."""
    if not isinstance(lines, Lines):
        raise TypeError(f"measure() takes a fracterra.Lines (ft.polyline()'s result), got {type(lines).__name__}")
    with lines._handle() as pl:
        return pl.measure()


def fpl_study(rng: str = "uniform", spreads=(0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5), depths=(8,),
              count: int = 100, seed: int = 1, box_counting: bool = True, progress=None) -> dict:
    """The FPL ensemble study of seed 003 (Nikulin), as `fracterra study fpl`
    runs it: for each spread s and depth r, `count` lines on the unit segment
    (seeds seed .. seed + count - 1) and the ensemble means with their
    standard errors of eta, chi, gamma, the mass and box-counting dimensions,
    beside the paper's fitted formulas (uniform: eta ~ 0.65 s, chi ~ 0.29 s,
    gamma ~ 2^(0.71 s^1.82 r); normal: 1.23, 0.5, 2^(1.34 sigma^1.58 r)).

    Returns {column: array} with the columns of the CLI's CSV: spread, depth,
    count, eta_mean, eta_se, chi_mean, chi_se, gamma_mean, gamma_se,
    mass_dimension_mean, ..., paper_eta, paper_chi, paper_gamma,
    paper_dimension; one row per (spread, depth), spreads outer.
    rng: uniform (urf(s)) or normal (nrf(sigma)).
    """
    lib = library()
    if not isinstance(rng, str) or rng.lower() not in _RNGS:
        raise InvalidArgumentError(f"rng must be one of uniform, normal, got {rng!r}")
    s = np.ascontiguousarray(np.atleast_1d(np.asarray(spreads, dtype=np.float64)))
    d = np.atleast_1d(np.asarray(depths))
    if s.ndim != 1 or d.ndim != 1 or d.dtype.kind not in "iu":
        raise TypeError("spreads is a sequence of numbers and depths a sequence of integers")
    d = np.ascontiguousarray(d, dtype=np.int32)
    rows = (FplStudyRow * (len(s) * len(d)))()
    bridge = _ProgressBridge(progress)
    status = lib.ft_fpl_study(_RNGS[rng.lower()], s.ctypes.data_as(POINTER(c_double)), len(s),
                              d.ctypes.data_as(POINTER(c_int32)), len(d), int(count), int(seed),
                              1 if box_counting else 0, bridge.c_fn, None, ctypes.cast(rows, c_void_p), len(rows))
    bridge.reraise()
    lib.check(status)
    return {name: np.array([getattr(r, name) for r in rows], dtype=np.int32 if name in ("depth", "count") else np.float64)
            for name, _ in FplStudyRow._fields_}


def coastline(z, level: float = 0.0, *, quantile: bool = False, world: bool = False) -> Lines:
    """The coastline (level set) of terrain `z` at height `level` (quantile=True:
    the level is that share of the samples below it) as Lines, as `fracterra
    coastline` writes it: x = column, y = row, z = the level; world=True: x
    and y in world units (z's world size across x, the same spacing in y)."""
    lib = library()
    if not math.isfinite(level) or (quantile and not 0 <= level <= 1):
        raise InvalidArgumentError(f"the coastline level must be finite (a quantile in [0, 1]), got {level}")
    with to_library(z) as hf:
        out = c_void_p()
        lib.check(lib.ft_coastline(hf.handle, float(level), 1 if quantile else 0, byref(out)))
        lines = Lines._from_handle(Polylines(out))
        width = hf.width
    if world:
        ws = float(getattr(z, "world_size", 0.0) or 0.0)
        if not ws > 0:
            raise InvalidArgumentError("world=True: the terrain records no world size (set its .world_size)")
        lines.xyz[:, :2] *= ws / (width - 1)
    return lines


def _annotate() -> None:
    from inspect import Parameter
    ko = Parameter.KEYWORD_ONLY
    document(polyline, [Parameter("method", Parameter.POSITIONAL_OR_KEYWORD, default="fpl", annotation=Any),
                        Parameter("base", ko, default=None), Parameter("plane_normal", ko, default=None),
                        Parameter("threads", ko, default=0), Parameter("progress", ko, default=None)],
             [("Settings", Table("polyline", skip=("threads", "method")))])


__all__ = ["Lines", "polyline", "measure", "fpl_study", "coastline"]
