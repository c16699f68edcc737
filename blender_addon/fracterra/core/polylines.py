# SPDX-License-Identifier: GPL-3.0-or-later
"""Fractal polylines (FPL, Koch, dragon, Sierpinski, IFS, profile), their
measures, and the ft_polylines handle."""

import array
import ctypes
import itertools
import math
from ctypes import POINTER, byref, c_double, c_int64, c_void_p

from . import params as params_mod
from .handle import LibraryHandle
from .binding import HurstResult, PolylineStats, enum_values, library
from .errors import InvalidArgumentError
from .terrain import _ProgressBridge


# Buffer formats with the same bits as array.array's "d" and "q" (numpy's int64 is "l").
_SAME_BITS = {"d": ("d", "<d", "=d"), "q": ("q", "l", "<q", "<l", "=q", "=l")}


def _contiguous(buf, typecode):
    """A writable array.array(typecode) holding the values of `buf`: one copy of its
    bytes when the buffer already has that item type, element by element otherwise."""
    try:
        view = memoryview(buf)
    except TypeError:  # a list or other plain sequence
        return array.array(typecode, buf)
    if view.format in _SAME_BITS[typecode] and view.c_contiguous:
        out = array.array(typecode)
        out.frombytes(view.cast("B"))
        return out
    return array.array(typecode, buf)


class Polylines(LibraryHandle):
    """Owns an ft_polylines*; a set of polylines sharing one vertex array.
    Use as a context manager (or call close())."""

    _free = "ft_polylines_free"

    @classmethod
    def from_lines(cls, lines, radii=None):
        """A set from a list of lines, each a list of (x, y, z); radii: matching lists or None."""
        xyz = array.array("d", [c for line in lines for p in line for c in p[:3]])
        rad = array.array("d", [r for line in radii for r in line]) if radii else None
        offsets = array.array("q", itertools.accumulate((len(line) for line in lines), initial=0))
        return cls.from_arrays(xyz, rad, offsets)

    @classmethod
    def from_arrays(cls, xyz, radii, offsets):
        """A set from flat buffers (array.array, 1-D numpy arrays, any sequence with
        the buffer protocol): xyz float64 (3 per vertex), radii float64 (1 per vertex) or None,
        offsets int64 (line k is vertices offsets[k] .. offsets[k + 1] - 1)."""
        lib = library()
        xyz = _contiguous(xyz, "d")
        rad = _contiguous(radii, "d") if radii is not None else None
        offsets = _contiguous(offsets, "q")
        out = c_void_p()

        def ptr(buf, ctype):
            return (ctype * len(buf)).from_buffer(buf) if buf is not None and len(buf) else None
        lib.check(lib.ft_polylines_create(ptr(xyz, c_double), ptr(rad, c_double), len(xyz) // 3,
                                          ptr(offsets, c_int64), len(offsets) - 1, byref(out)))
        return cls(out)

    @property
    def line_count(self):
        return self._lib.ft_polylines_line_count(self.handle)

    @property
    def vertex_count(self):
        return self._lib.ft_polylines_vertex_count(self.handle)

    def offsets(self):
        n = self.line_count + 1
        return array.array("q", ctypes.string_at(self._lib.ft_polylines_offsets(self.handle), 8 * n))

    def xyz(self):
        """3 * vertex_count floats (array.array('d'))."""
        n = 3 * self.vertex_count
        return array.array("d", ctypes.string_at(self._lib.ft_polylines_xyz(self.handle), 8 * n)) if n else array.array("d")

    def radii(self):
        n = self.vertex_count
        return array.array("d", ctypes.string_at(self._lib.ft_polylines_radii(self.handle), 8 * n)) if n else array.array("d")

    def lines(self):
        """[(xyz list of tuples, radii list)] per line (for small sets and tests)."""
        xyz, rad, off = self.xyz(), self.radii(), self.offsets()
        return [([tuple(xyz[3 * i:3 * i + 3]) for i in range(off[k], off[k + 1])], list(rad[off[k]:off[k + 1]]))
                for k in range(len(off) - 1)]

    def measure(self):
        """Seed 003's measures of line 0 (eta, chi, gamma, mass dimension) and the box dimension."""
        s = PolylineStats()
        s.struct_size = ctypes.sizeof(PolylineStats)
        self._lib.check(self._lib.ft_polyline_measure(self.handle, byref(s)))
        return {name: getattr(s, name) for name, _ in PolylineStats._fields_
                if not name.startswith(("reserved", "struct_size"))}



def generate_polylines(values=None, base=None, plane_normal=None, progress=None, threads=0, **overrides):
    """Generates polylines; returns a Polylines (close it, or use `with`).

    values/overrides: settings by name (params.POLYLINE_PARAMS): method='FPL',
    rng='UNIFORM', spread=0.1, depth=8, min_length=0, seed=1, ...
    base: None (the unit segment) or a list of >= 2 (x, y, z) nodes.
    """
    lib = library()
    p = lib.polyline_params_type()
    lib.check(lib.ft_polyline_params_init(byref(p)))
    merged = dict(values or {})
    merged.update(overrides)
    params_mod.fill_struct(p, merged, params_mod.POLYLINE_PARAMS)
    base_buf = None
    if base is not None:
        base_buf = array.array("d", [c for pt in base for c in pt[:3]])
        if len(base_buf) < 6 or len(base_buf) % 3:
            raise InvalidArgumentError(f"the base polyline needs at least 2 points of 3 coordinates, got {len(base_buf) / 3:g}")
    return run_polyline(lib, p, base_buf, plane_normal, progress, threads)


def run_polyline(lib, p, base_xyz, plane_normal, progress, threads):
    """Generates from filled params p: base_xyz is None or a writable buffer of
    3 * n doubles (array.array('d') or a C-contiguous float64 numpy array) that
    stays alive for the call; returns a Polylines."""
    p.threads = threads
    if base_xyz is not None:
        n = len(base_xyz) if not hasattr(base_xyz, "size") else base_xyz.size
        p.base = ctypes.cast((c_double * n).from_buffer(base_xyz), POINTER(c_double))
        p.base_count = n // 3
    if plane_normal is not None:
        p.plane_normal[:] = [float(c) for c in plane_normal]
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    out = c_void_p()
    status = lib.ft_polyline_generate(byref(p), byref(out))
    bridge.reraise()
    lib.check(status)
    return Polylines(out)


def hurst_of_heightfield(hf, method="AUTO"):
    """{'hurst', 'dimension', 'std_error', 'estimator', 'reason', ...} of a heightfield (analysis.h).

    AUTO is the library's recommendation for the grid (the one `fracterra analyze`
    reports); 'estimator' names the method used and 'reason' says why.
    """
    lib = library()
    p = lib.hurst_params_type()
    lib.check(lib.ft_hurst_params_init(byref(p)))
    methods = enum_values("hurst", "method")
    p.method = methods[method]
    r = HurstResult(struct_size=ctypes.sizeof(HurstResult))
    lib.check(lib.ft_hurst_heightfield(hf.handle, byref(p), byref(r)))
    out = {name: getattr(r, name) for name, _ in HurstResult._fields_}
    out["estimator"] = next(k for k, v in methods.items() if v == r.method).lower()
    out["reason"] = (r.auto_reason_text or b"").decode() if method == "AUTO" else "asked for by name"
    return out




def coastline(hf, level, quantile=False):
    """The level set of `hf` as Polylines in sample units (x = column, y = row, z = level)."""
    lib = library()
    if not math.isfinite(level):
        raise InvalidArgumentError(f"the coastline level must be finite, got {level}")
    out = c_void_p()
    lib.check(lib.ft_coastline(hf.handle, level, 1 if quantile else 0, byref(out)))
    return Polylines(out)
