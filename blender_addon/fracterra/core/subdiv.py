# SPDX-License-Identifier: GPL-3.0-or-later
"""Fractalizing polygon meshes with OpenSubdiv in the library (fracterra/subdiv.h)."""

import array
import ctypes
from ctypes import byref, c_float, c_int32, c_void_p

from .handle import LibraryHandle
from .binding import enum_values, library
from .terrain import _ProgressBridge, as_pointer as _ptr


class Mesh(LibraryHandle):
    """Owns an ft_mesh*: positions (3 floats per vertex), face sizes and indices."""

    _free = "ft_mesh_free"

    @classmethod
    def create(cls, positions, face_sizes, face_indices, crease_pairs=None, crease_sharpness=None):
        """positions: array('f') of 3 per vertex; face_sizes/face_indices: int32 buffers
        (array 'i' or 'I'); creases: vertex pairs and sharpness in [0, 10]."""
        lib = library()
        pairs = crease_pairs if crease_pairs is not None else array.array("i")
        sharp = crease_sharpness if crease_sharpness is not None else array.array("f")
        out = c_void_p()
        lib.check(lib.ft_mesh_create(_ptr(positions, c_float), len(positions) // 3, _ptr(face_sizes, c_int32),
                                     len(face_sizes), _ptr(face_indices, c_int32), _ptr(pairs, c_int32),
                                     _ptr(sharp, c_float), len(sharp), byref(out)))
        return cls(out)

    def _copy(self, pointer, n, fmt, size):
        return array.array(fmt, ctypes.string_at(pointer, n * size)) if n else array.array(fmt)

    def positions(self):
        return self._copy(self._lib.ft_mesh_positions(self.handle), 3 * self._lib.ft_mesh_vertex_count(self.handle), "f", 4)

    def face_sizes(self):
        return self._copy(self._lib.ft_mesh_face_sizes(self.handle), self._lib.ft_mesh_face_count(self.handle), "I", 4)

    def face_indices(self):
        return self._copy(self._lib.ft_mesh_face_indices(self.handle),
                          self._lib.ft_mesh_face_index_count(self.handle), "I", 4)



def fractalize(mesh, levels=4, hurst=0.8, sigma=0.1, seed=1, scheme="CATMARK", mode="MIDPOINT",
               fix_boundary=False, scale_by_edge_length=False, weights=None, threads=0, progress=None):
    """A new Mesh: `mesh` subdivided `levels` times with fractal displacements.

    scheme and mode are the identifiers of the library's enum items (CATMARK, LOOP,
    BILINEAR; MIDPOINT, ADDITIONS), as `fracterra params` lists them."""
    lib = library()
    p = lib.fractalize_params_type()
    lib.check(lib.ft_fractalize_params_init(byref(p)))
    p.levels, p.hurst, p.sigma, p.seed = levels, hurst, sigma, seed
    p.scheme = enum_values("fractalize", "scheme")[scheme]
    p.mode = enum_values("fractalize", "mode")[mode]
    p.fix_boundary, p.scale_by_edge_length, p.threads = int(fix_boundary), int(scale_by_edge_length), threads
    weight_buf = None
    if weights is not None:
        weight_buf = array.array("f", weights)
        p.weights = ctypes.cast(_ptr(weight_buf, c_float), ctypes.POINTER(c_float))
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    out = c_void_p()
    status = lib.ft_fractalize(mesh.handle, byref(p), byref(out))
    bridge.reraise()
    lib.check(status)
    return Mesh(out)
