# SPDX-License-Identifier: GPL-3.0-or-later
"""Terrain and profile generation through the C ABI, and the heightfield handle."""

import array
import ctypes
from ctypes import POINTER, byref, c_double, c_float, c_void_p

from . import params as params_mod
from .errors import CancelledError, InvalidArgumentError
from .handle import LibraryHandle
from .binding import PROGRESS_FN, library


def float_array(n, fill=0.0):
    """A zero-initialised array.array('f') of n floats (fast: repeats one element)."""
    return array.array("f", [fill]) * n


def index_array(n):
    """A zeroed array.array('I') of n indices. Unsigned on purpose: Blender's
    foreach_set copies a buffer with memcpy only when its format matches the
    property ('I' for the UNSIGNED index properties); otherwise it converts
    element by element, about 10x slower. The library writes int32 values
    in 0..2^31 - 1, whose bits are the same."""
    return array.array("I", [0]) * n


def as_pointer(buf, ctype):
    """A zero-copy ctypes view of a writable buffer (array.array, bytearray)."""
    if len(buf) == 0:
        return None
    return (ctype * len(buf)).from_buffer(buf)


class Heightfield(LibraryHandle):
    """Owns an ft_heightfield*; use as a context manager (or call close())."""

    _free = "ft_heightfield_free"

    @classmethod
    def from_values(cls, width, height, values):
        """A library heightfield holding `values` (width * height floats, row-major)."""
        lib = library()
        buf = array.array("f", values)
        if len(buf) != width * height:
            raise InvalidArgumentError(f"{len(buf)} values given for a {width} x {height} heightfield")
        out = c_void_p()
        lib.check(lib.ft_heightfield_create(width, height, as_pointer(buf, c_float), byref(out)))
        return cls(out)

    @property
    def world_size(self):
        """Extent along x in scene units the library recorded (0 if unknown)."""
        return self._lib.ft_heightfield_world_size(self.handle)

    @property
    def width(self):
        return self._lib.ft_heightfield_width(self.handle)

    @property
    def height(self):
        return self._lib.ft_heightfield_height(self.handle)

    def to_array(self):
        """A copy of the samples as array.array('f'), row-major (row = y)."""
        out = float_array(self.width * self.height)
        self._lib.check(self._lib.ft_heightfield_copy(self.handle, as_pointer(out, c_float), len(out)))
        return out

    def stats(self):
        """{'min', 'max', 'mean', 'std'} of the samples."""
        v = [c_double() for _ in range(4)]
        self._lib.check(self._lib.ft_heightfield_stats(self.handle, *[byref(x) for x in v]))
        return dict(zip(("min", "max", "mean", "std"), (x.value for x in v)))



class _ProgressBridge:
    """Adapts a Python `progress(fraction) -> bool` (True cancels) to ft_progress_fn.

    An exception raised by the callback cancels the call and is re-raised
    afterwards instead of being swallowed by ctypes.
    """

    def __init__(self, progress):
        self.progress = progress
        self.error = None
        self.c_fn = PROGRESS_FN(self._call) if progress else PROGRESS_FN()

    def _call(self, _user, fraction):
        try:
            return 1 if self.progress(fraction) else 0
        except BaseException as e:  # noqa: B036 - must not unwind through C
            self.error = e
            return 1

    def reraise(self):
        if self.error is not None:
            raise self.error


def terrain_struct(values=None, **overrides):
    """An ft_terrain_params initialised by the library, then filled from settings."""
    lib = library()
    p = lib.terrain_params_type()
    lib.check(lib.ft_terrain_params_init(byref(p)))
    merged = dict(values or {})
    merged.update(overrides)
    params_mod.fill_struct(p, merged)
    return p


def mandelbrot_level_height(nu, values=None, **overrides):
    """The height at which a Mandelbrot terrain of these settings has its
    curve of escape time `nu` (an equipotential): contour it there."""
    lib = library()
    p = terrain_struct(values, **overrides)
    out = c_double()
    lib.check(lib.ft_mandelbrot_level_height(byref(p), float(nu), byref(out)))
    return out.value


def attach_reference(p, reference):
    """Points ft_terrain_params `p` at a reference grid (size, values), size = 2^m + 1
    and size^2 floats row-major, or at none (None). Returns the buffer the struct
    points into: keep it alive as long as `p` is used."""
    if reference is None:
        return None
    size, values = reference
    buf = array.array("f", values)
    if len(buf) != size * size:
        raise InvalidArgumentError(f"the reference grid has {len(buf)} values; size {size} needs {size * size}")
    p.reference = ctypes.cast(as_pointer(buf, c_float), POINTER(c_float))
    p.reference_size = size
    return buf


def attach_map(p, field, mask, what):
    """Points the map field `field` of params struct `p` (with `field`_width and
    `field`_height beside it) at `mask` = (width, height, values): width x height
    floats in [0, 1], row-major, row 0 at the terrain's row 0 (an array.array('f')
    or anything with tobytes() giving float32 is taken as is, other sequences are
    converted). None leaves the struct as it is. Returns the buffer the struct
    points into: keep it alive while `p` is used."""
    if mask is None:
        return None
    width, height, values = mask
    if isinstance(values, array.array) and values.typecode == "f":
        buf = values
    elif str(getattr(values, "dtype", "")) == "float32":  # a numpy array: copied in one go
        buf = array.array("f")
        buf.frombytes(values.tobytes())
    else:
        buf = array.array("f", values)
    if len(buf) != width * height:
        raise InvalidArgumentError(f"{what} has {len(buf)} values; {width} x {height} needs {width * height}")
    setattr(p, field, ctypes.cast(as_pointer(buf, c_float), POINTER(c_float)))
    setattr(p, field + "_width", width)
    setattr(p, field + "_height", height)
    return buf


def attach_falloff_mask(p, mask):
    """The custom falloff's mask (see attach_map)."""
    return attach_map(p, "falloff_mask", mask, "the falloff mask")


def generate_terrain(values=None, reference=None, progress=None, threads=0, falloff_mask=None, **overrides):
    """Generates a terrain; returns a Heightfield (close it, or use `with`).

    values/overrides: settings by name (see params.TERRAIN_PARAMS), e.g.
    method='MIDPOINT', levels=10, hurst=0.8, sigma=1.0, seed=7.
    reference: None or (size, values) with size = 2^m + 1 and size^2 floats,
    row-major. falloff_mask: None or (width, height, values) for falloff='CUSTOM'
    (see attach_falloff_mask). progress: None or a callable(fraction) returning
    True to cancel (raises CancelledError).
    """
    p = terrain_struct(values, **overrides)
    p.threads = threads
    _ref_buf = attach_reference(p, reference)
    _mask_buf = attach_falloff_mask(p, falloff_mask)
    return generate_from_struct(p, progress)


def generate_from_struct(p, progress=None):
    """ft_terrain_generate of a filled ft_terrain_params `p` (the Python package
    fills it from keyword arguments); returns a Heightfield."""
    lib = library()
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    out = c_void_p()
    status = lib.ft_terrain_generate(byref(p), byref(out))
    bridge.reraise()
    lib.check(status)
    return Heightfield(out)


def terrain_side(levels):
    """2^levels + 1, or -1 when levels is outside the library's range."""
    return library().ft_terrain_side(levels)


def generate_profile(levels=10, hurst=0.8, sigma=1.0, seed=1, reference=None, progress=None):
    """Voss 1D midpoint displacement: 2^levels + 1 floats as array.array('f')."""
    lib = library()
    p = lib.profile_params_type()
    as_params = byref(p)  # a subclass of ProfileParams when the library's struct is larger
    lib.check(lib.ft_profile_params_init(as_params))
    p.levels, p.hurst, p.sigma, p.seed = levels, hurst, sigma, seed
    ref_buf = None
    if reference is not None:
        ref_buf = array.array("f", reference)
        p.reference = ctypes.cast(as_pointer(ref_buf, c_float), POINTER(c_float))
        p.reference_size = len(ref_buf)
    n = lib.ft_profile_length(levels)
    if n < 0:
        # Let the library word the range error.
        lib.check(lib.ft_profile_generate(as_params, None, 0))
    out = float_array(n)
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    status = lib.ft_profile_generate(as_params, as_pointer(out, c_float), len(out))
    bridge.reraise()
    lib.check(status)
    return out


__all__ = ["Heightfield", "generate_terrain", "generate_from_struct", "generate_profile", "terrain_struct", "terrain_side",
           "float_array", "index_array", "as_pointer", "CancelledError"]
