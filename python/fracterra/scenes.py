# SPDX-License-Identifier: GPL-3.0-or-later
"""POV-Ray scenes and renders (fracterra/povray.h), and Feder's clouds
(fracterra/analysis.h): pictures of terrains and polylines."""

from __future__ import annotations

import os
from ctypes import POINTER, byref, c_uint16
from typing import Any

import numpy as np

from .arrays import to_library, world_of
from .core import povray
from .core.binding import library
from .core.errors import InvalidArgumentError
from .keywords import Table, document, split

_LINE_KINDS = ("line", "lightning", "coastline")


def pov_scene(path, terrain=None, *, lines=(), rivers=None, vertical_scale: float = 1.0, sea_level=None,
              camera=None, sun=None, colors=None) -> None:
    """Writes a POV-Ray scene to `path` (and the terrain's PNG beside it), as
    `fracterra scene` does: the camera framed on the content, sun and sky, the
    sea, the terrain's material by altitude and slope, polylines as sweeps.

    terrain: a Terrain (it spans x 0..world_size, y in the same spacing; a
    plain array: 10 units) or None. lines: Lines, or (Lines, kind[, radius])
    with kind line, lightning or coastline, in the terrain's world units.
    rivers: a Rivers (ft.rivers()), drawn as water. sea_level: a height
    (None: the terrain's own sea, a Terrain's sea_level). camera:
    {'azimuth', 'elevation', 'fov', 'aspect'} in degrees. sun: {'azimuth',
    'elevation'}. colors: (rows, columns, 3) linear RGB painted on the
    terrain (e.g. ft.splat(z, color=True)).
    """
    from .polylines import Lines
    keep = []
    hf = None
    try:
        sets = []
        for entry in (lines if isinstance(lines, (list, tuple)) else [lines]):
            entry = entry if isinstance(entry, tuple) else (entry, "line")
            if not isinstance(entry[0], Lines) or len(entry) > 3:
                raise TypeError(f"lines are fracterra.Lines or (Lines, kind[, radius]), got {entry!r}")
            kind = entry[1].lower() if isinstance(entry[1], str) else entry[1]
            if kind not in _LINE_KINDS:
                raise InvalidArgumentError(f"a line set's kind is one of {', '.join(_LINE_KINDS)}, got {entry[1]!r}")
            handle = entry[0]._handle()
            keep.append(handle)
            sets.append((handle, kind.upper(), float(entry[2]) if len(entry) > 2 else 0.0))
        river_lines = None
        if rivers is not None:
            from .polylines import Lines as _L
            river_lines = _L(rivers.xyz, rivers.radii, rivers.offsets)._handle()
            keep.append(river_lines)
        wx = wy = 1.0
        if terrain is not None:
            ws, _o, own_sea = world_of(terrain)
            hf = to_library(terrain)
            wx = ws if ws > 0 else 10.0
            wy = wx * (hf.height - 1) / max(hf.width - 1, 1)
            if sea_level is None and own_sea == own_sea:  # not NaN
                sea_level = own_sea
        flat = None
        if colors is not None:
            c = np.ascontiguousarray(colors, dtype=np.float32)
            if terrain is None or c.shape != (hf.height, hf.width, 3):
                raise InvalidArgumentError(f"colors must be (rows, columns, 3) of the terrain, got {c.shape}")
            flat = c.ravel()
        povray.write_scene(os.fspath(path), hf, wx, wy, float(vertical_scale), sea_level, sets, camera, sun,
                           flat, rivers=river_lines)
    finally:
        for h in keep:
            h.close()
        if hf is not None:
            hf.close()


def render(pov_path, png_path, width: int = 640, height: int = 480, antialias: float = 0.3) -> None:
    """Renders the scene `pov_path` with POV-Ray into `png_path` (written atomically); the library's
    message (with POV-Ray's error lines) when POV-Ray is missing or fails."""
    povray.render(os.fspath(pov_path), os.fspath(png_path), int(width), int(height), float(antialias))


def clouds(z, **settings) -> np.ndarray:
    """Feder's clouds of `z` (seed 001), as `fracterra clouds` draws them:
    black below the threshold, above it grey = ln(e / e_T) / ln(e_max / e_T),
    as a (rows, columns) uint16 array (0..255, or 0..65535 with bit_depth=16)."""
    lib = library()
    table = Table("clouds")
    given = split(settings, {"clouds": table})["clouds"]
    p = lib.clouds_params_type()
    lib.check(lib.ft_clouds_params_init(byref(p)))
    table.fill(p, given)
    with to_library(z) as hf:
        out = np.empty((hf.height, hf.width), np.uint16)
        lib.check(lib.ft_clouds(hf.handle, byref(p), out.ctypes.data_as(POINTER(c_uint16)), out.size))
    return out


def _annotate() -> None:
    from inspect import Parameter
    document(clouds, [Parameter("z", Parameter.POSITIONAL_OR_KEYWORD, annotation=Any)],
             [("Settings", Table("clouds"))])


__all__ = ["pov_scene", "render", "clouds"]
