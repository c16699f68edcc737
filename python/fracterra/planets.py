# SPDX-License-Identifier: GPL-3.0-or-later
"""Fractal planets as numpy arrays (fracterra/planet.h): cube faces and their
patches, equirectangular maps, the closed cube-sphere and icosphere meshes,
heights at given directions, the sea's height and the angular spectrum."""

from __future__ import annotations

from ctypes import POINTER, byref, c_double, c_float, c_int32, c_int64, c_void_p
from typing import Any

import numpy as np

from .arrays import from_library
from .core.binding import library
from .core.errors import InvalidArgumentError
from .core.terrain import Heightfield, _ProgressBridge
from .keywords import Table, document, split

_OUTPUTS = ("equirect", "face", "faces", "mesh", "icosphere", "heights", "spectrum")


def _struct(settings, threads, bridge):
    lib = library()
    table = Table("planet", skip=("threads",))
    given = split(settings, {"planet": table}, ("output", "level", "face", "window", "width", "height",
                                               "vertical_scale", "directions", "lmax", "threads", "progress"))
    p = lib.planet_params_type()
    lib.check(lib.ft_planet_params_init(byref(p)))
    table.fill(p, given["planet"])
    p.threads = threads
    p.progress = bridge.c_fn
    return p


def planet(output: str = "equirect", *, level: int = 8, face: int = 0, window=None, width: int = 1024,
           height: int = 512, vertical_scale: float = 1.0, directions=None, lmax: int = 64, threads: int = 0,
           progress=None, **settings) -> Any:
    """A fractal planet (as `fracterra planet` makes it), by `output`:

    equirect: a (height, width) Terrain in metres above the radius.
    face: cube face `face` (0..5) at `level` (2^level + 1 samples a side), or
    its patch window=(x0, y0, width, height): a Terrain whose world size is the
    patch's width in metres (a patch is those samples of the whole face, bit for bit).
    faces: the six faces as a (6, n, n) float32 array.
    mesh: the closed cube-sphere of `level`: {'xyz' (v, 3) float32 metres,
    'quads' (f, 4) int32, 'heights' (v,) float32}, at radius + vertical_scale x height.
    icosphere: the same for the icosphere of `level` ('triangles' (f, 3)).
    heights: the heights (float32, metres) at `directions`, an (n, 3) array of vectors.
    spectrum: the angular power spectrum C_l, l = 0..lmax (metres^2).
    """
    lib = library()
    if output not in _OUTPUTS:
        raise InvalidArgumentError(f"output must be one of {', '.join(_OUTPUTS)}, got {output!r}")
    bridge = _ProgressBridge(progress)
    p = _struct(settings, threads, bridge)
    out = c_void_p()
    if output == "equirect":
        status = lib.ft_planet_equirect(byref(p), int(width), int(height), byref(out))
    elif output in ("face", "faces"):
        side = 2 ** int(level) + 1
        if output == "faces":
            return np.stack([planet("face", level=level, face=k, threads=threads, **settings) for k in range(6)])
        x0, y0, w, h = window if window is not None else (0, 0, side, side)
        status = lib.ft_planet_face(byref(p), int(level), int(face), int(x0), int(y0), int(w), int(h), byref(out))
    elif output in ("mesh", "icosphere"):
        return _mesh(lib, p, output, int(level), float(vertical_scale), bridge)
    elif output == "heights":
        d = np.ascontiguousarray(directions, dtype=np.float64)
        if d.ndim != 2 or d.shape[1] != 3 or not np.all(np.isfinite(d)):
            raise InvalidArgumentError(f"directions must be an (n, 3) array of finite vectors, got shape {d.shape}")
        z = np.empty(len(d), np.float32)
        lib.check(lib.ft_planet_heights(byref(p), d.ctypes.data_as(POINTER(c_double)), len(d),
                                        z.ctypes.data_as(POINTER(c_float))))
        return z
    else:
        power = np.empty(int(lmax) + 1, np.float64)
        lib.check(lib.ft_planet_power_spectrum(byref(p), int(lmax), power.ctypes.data_as(POINTER(c_double)),
                                               power.size))
        return power
    bridge.reraise()
    lib.check(status)
    with Heightfield(out) as hf:
        return from_library(hf)


def _mesh(lib, p, output, level, vertical_scale, bridge) -> dict:
    nv, nf = c_int64(), c_int64()
    ico = output == "icosphere"
    lib.check((lib.ft_planet_icosphere_counts if ico else lib.ft_planet_mesh_counts)(level, byref(nv), byref(nf)))
    corners = 3 if ico else 4
    xyz = np.empty((nv.value, 3), np.float32)
    faces = np.empty((nf.value, corners), np.int32)
    heights = np.empty(nv.value, np.float32)
    fn = lib.ft_planet_icosphere if ico else lib.ft_planet_mesh
    status = fn(byref(p), level, vertical_scale, xyz.ctypes.data_as(POINTER(c_float)), xyz.size,
                faces.ctypes.data_as(POINTER(c_int32)), faces.size, heights.ctypes.data_as(POINTER(c_float)),
                heights.size)
    bridge.reraise()
    lib.check(status)
    return {"xyz": xyz, "triangles" if ico else "quads": faces, "heights": heights}


def sea_height(**settings) -> float:
    """The planet's sea height in metres above the radius (NaN without a sea)."""
    lib = library()
    out = c_double()
    lib.check(lib.ft_planet_sea_height(byref(_struct(settings, 0, _ProgressBridge(None))), byref(out)))
    return out.value


def _annotate() -> None:
    from inspect import Parameter, signature
    leading = [p for p in signature(planet).parameters.values() if p.kind is not Parameter.VAR_KEYWORD]
    document(planet, leading, [("Planet settings", Table("planet", skip=("threads",)))])


__all__ = ["planet", "sea_height"]
