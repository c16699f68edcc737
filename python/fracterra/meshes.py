# SPDX-License-Identifier: GPL-3.0-or-later
"""Fractalizing polygon meshes (fracterra/subdiv.h): OpenSubdiv's
subdivision with fractal displacements, from and to numpy arrays."""

from __future__ import annotations

import ctypes
from ctypes import POINTER, byref, c_float, c_int32, c_void_p
from typing import Any

import numpy as np

from .core.binding import library
from .core.errors import InvalidArgumentError
from .core.subdiv import Mesh
from .core.terrain import _ProgressBridge
from .keywords import Table, document, split


def _faces(faces, vertex_count):
    """(face sizes, flat indices) of an (f, k) array or a list of index sequences."""
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        sizes = np.full(len(faces), faces.shape[1], np.int32)
        flat = faces.ravel()
    else:
        faces = [np.asarray(f).ravel() for f in faces]
        sizes = np.array([len(f) for f in faces], np.int32)
        flat = np.concatenate(faces) if faces else np.zeros(0, np.int32)
    if flat.dtype.kind not in "iu" and flat.size:
        raise TypeError(f"faces hold vertex indices (integers), got dtype {flat.dtype}")
    if sizes.size == 0 or np.any(sizes < 3):
        raise InvalidArgumentError("every face needs at least 3 vertices, and there must be a face")
    if flat.size and (flat.min() < 0 or flat.max() >= vertex_count):
        raise InvalidArgumentError(f"face indices must lie in [0, {vertex_count}), got [{flat.min()}, {flat.max()}]")
    return sizes, np.ascontiguousarray(flat, dtype=np.int32)


def fractalize(vertices, faces, *, weights=None, threads: int = 0, progress=None, **settings) -> dict:
    """`vertices` (n, 3) and `faces` (an (f, k) index array or a list of index
    sequences) subdivided `levels` times with fractal displacements, as
    `fracterra fractalize` does. Returns {'vertices' (m, 3) float32,
    'face_sizes' (g,) int32, 'face_indices' (sum of sizes,) int32, 'faces'
    (g, k) int32 when every face has k corners, else a list}.
    weights: None or one displacement weight per input vertex, in [0, 1]."""
    lib = library()
    table = Table("fractalize", skip=("threads",))
    given = split(settings, {"fractalize": table}, ("weights", "threads", "progress"))["fractalize"]
    v = np.ascontiguousarray(vertices, dtype=np.float32)
    if v.ndim != 2 or v.shape[1] != 3 or not np.all(np.isfinite(v)):
        raise InvalidArgumentError(f"vertices must be an (n, 3) array of finite coordinates, got shape {v.shape}")
    sizes, flat = _faces(faces, len(v))
    p = lib.fractalize_params_type()
    lib.check(lib.ft_fractalize_params_init(byref(p)))
    table.fill(p, given)
    p.threads = threads
    w = None
    if weights is not None:
        w = np.ascontiguousarray(weights, dtype=np.float32)
        if w.shape != (len(v),):
            raise InvalidArgumentError(f"weights: one per vertex ({len(v)}), got shape {w.shape}")
        p.weights = w.ctypes.data_as(POINTER(c_float))
    out = c_void_p()
    lib.check(lib.ft_mesh_create(v.ctypes.data_as(POINTER(c_float)), len(v), sizes.ctypes.data_as(POINTER(c_int32)),
                                 len(sizes), flat.ctypes.data_as(POINTER(c_int32)), None, None, 0, byref(out)))
    with Mesh(out) as mesh:
        bridge = _ProgressBridge(progress)
        p.progress = bridge.c_fn
        made = c_void_p()
        status = lib.ft_fractalize(mesh.handle, byref(p), byref(made))
        bridge.reraise()
        lib.check(status)
    with Mesh(made) as m:
        xyz = np.frombuffer(m.positions(), dtype=np.float32).reshape(-1, 3).copy()
        fs = np.frombuffer(m.face_sizes(), dtype=np.uint32).astype(np.int32)
        fi = np.frombuffer(m.face_indices(), dtype=np.uint32).astype(np.int32)
    split_at = np.cumsum(fs)[:-1]
    uniform = fs.size and np.all(fs == fs[0])
    return {"vertices": xyz, "face_sizes": fs, "face_indices": fi,
            "faces": fi.reshape(-1, int(fs[0])) if uniform else np.split(fi, split_at)}


def _annotate() -> None:
    from inspect import Parameter
    pos, ko = Parameter.POSITIONAL_OR_KEYWORD, Parameter.KEYWORD_ONLY
    document(fractalize, [Parameter("vertices", pos, annotation=Any), Parameter("faces", pos, annotation=Any),
                          Parameter("weights", ko, default=None), Parameter("threads", ko, default=0),
                          Parameter("progress", ko, default=None)],
             [("Settings", Table("fractalize", skip=("threads",)))])


__all__ = ["fractalize"]
