"""Finding and loading libfracterra.so, and the ctypes signature of every symbol.

Search order: the path in the FRACTERRA_LIBRARY environment variable (when
set, it is the only candidate: an explicit choice must not silently fall back),
then the copy bundled in the add-on's `lib/` folder. The library is loaded
on first use, so the add-on registers even when it is missing and can say
what to do. A library whose ABI major version differs is refused.
"""

import ctypes
import os
import threading
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char_p, c_double, c_float, c_int32, c_int64,
                    c_size_t, c_uint32, c_uint64, c_void_p)
from pathlib import Path

from .errors import LibraryNotFoundError, error_for_status

ABI_MAJOR = 1
ENV_VAR = "FRACTERRA_LIBRARY"
LIBRARY_NAME = "libfracterra.so"
BUNDLED_PATH = Path(__file__).resolve().parent.parent / "lib" / LIBRARY_NAME

HOW_TO_FIX = (
    "Install the add-on zip built by `cmake --build build --target fracterra_blender_addon` "
    "(it bundles lib/libfracterra.so), or set the environment variable "
    f"{ENV_VAR} to the full path of libfracterra.so before starting Blender."
)

# ft_progress_fn: int32_t (*)(void* user, double fraction); non-zero cancels.
PROGRESS_FN = CFUNCTYPE(c_int32, c_void_p, c_double)


class TerrainParams(Structure):
    """ft_terrain_params (fracterra/terrain.h); layout checked against struct_size."""
    _fields_ = [
        ("struct_size", c_uint32),
        ("method", c_int32),
        ("levels", c_int32),
        ("width", c_int32),
        ("height", c_int32),
        ("hurst", c_double),
        ("sigma", c_double),
        ("seed", c_uint64),
        ("periodic", c_int32),
        ("threads", c_int32),
        ("reference", POINTER(c_float)),
        ("reference_size", c_int32),
        ("reference_scale", c_int32),
        ("octaves", c_int32),
        ("lacunarity", c_double),
        ("gain", c_double),
        ("basis", c_int32),
        ("variant", c_int32),
        ("frequency", c_double),
        ("offset", c_double),
        ("rotation", c_double),
        ("warp", c_double),
        ("progress", PROGRESS_FN),
        ("progress_user", c_void_p),
        ("world_size", c_double),  # ABI 1.1
    ]


class ProfileParams(Structure):
    """ft_profile_params (fracterra/terrain.h)."""
    _fields_ = [
        ("struct_size", c_uint32),
        ("levels", c_int32),
        ("hurst", c_double),
        ("sigma", c_double),
        ("seed", c_uint64),
        ("reference", POINTER(c_float)),
        ("reference_size", c_int32),
        ("reference_scale", c_int32),
        ("progress", PROGRESS_FN),
        ("progress_user", c_void_p),
    ]


class GridCounts(Structure):
    """ft_grid_counts (fracterra/mesh.h)."""
    _fields_ = [("vertices", c_int64), ("edges", c_int64), ("faces", c_int64), ("loops", c_int64)]


_HF = c_void_p  # ft_heightfield*, opaque
_PL = c_void_p  # ft_polylines*, opaque
_I32P = POINTER(c_int32)
_F32P = POINTER(c_float)
_F64P = POINTER(c_double)

# name: (restype, argtypes). Every symbol the binding uses is declared here.
SIGNATURES = {
    "ft_abi_version": (c_uint32, []),
    "ft_version_string": (c_char_p, []),
    "ft_last_error": (c_char_p, []),
    "ft_status_name": (c_char_p, [c_int32]),
    "ft_memory_cap": (c_uint64, []),
    "ft_set_memory_cap": (None, [c_uint64]),
    "ft_heightfield_create": (c_int32, [c_int32, c_int32, _F32P, POINTER(_HF)]),
    "ft_heightfield_width": (c_int32, [_HF]),
    "ft_heightfield_height": (c_int32, [_HF]),
    "ft_heightfield_data": (_F32P, [_HF]),
    "ft_heightfield_data_mut": (_F32P, [_HF]),
    "ft_heightfield_copy": (c_int32, [_HF, _F32P, c_size_t]),
    "ft_heightfield_stats": (c_int32, [_HF, _F64P, _F64P, _F64P, _F64P]),
    "ft_heightfield_free": (None, [_HF]),
    "ft_heightfield_world_size": (c_double, [_HF]),
    "ft_heightfield_set_world_size": (c_int32, [_HF, c_double]),
    "ft_polylines_create": (c_int32, [_F64P, _F64P, c_int64, POINTER(c_int64), c_int64, POINTER(_PL)]),
    "ft_polylines_line_count": (c_int64, [_PL]),
    "ft_polylines_vertex_count": (c_int64, [_PL]),
    "ft_polylines_xyz": (_F64P, [_PL]),
    "ft_polylines_radii": (_F64P, [_PL]),
    "ft_polylines_offsets": (POINTER(c_int64), [_PL]),
    "ft_polylines_free": (None, [_PL]),
    "ft_terrain_params_init": (c_int32, [POINTER(TerrainParams)]),
    "ft_terrain_generate": (c_int32, [POINTER(TerrainParams), POINTER(_HF)]),
    "ft_terrain_side": (c_int32, [c_int32]),
    "ft_profile_params_init": (c_int32, [POINTER(ProfileParams)]),
    "ft_profile_generate": (c_int32, [POINTER(ProfileParams), _F32P, c_size_t]),
    "ft_profile_length": (c_int64, [c_int32]),
    "ft_grid_counts_get": (c_int32, [c_int32, c_int32, POINTER(GridCounts)]),
    "ft_grid_vertices": (c_int32, [_HF, c_double, c_double, c_double, _F32P, c_size_t]),
    "ft_grid_heights": (c_int32, [_HF, c_double, _F32P, c_size_t, c_size_t]),
    "ft_grid_topology": (c_int32, [c_int32, c_int32, _I32P, _I32P, c_size_t, _I32P, c_size_t,
                                   _I32P, _I32P, c_size_t]),
    "ft_grid_uvs": (c_int32, [c_int32, c_int32, _F32P, c_size_t]),
}


class Library:
    """The loaded library: attribute access gives the declared functions."""

    def __init__(self, path):
        self.path = Path(path)
        try:
            self._dll = ctypes.CDLL(str(self.path))
        except OSError as e:
            raise LibraryNotFoundError(f"cannot load {self.path}: {e}. {HOW_TO_FIX}") from None
        missing = []
        for name, (restype, argtypes) in SIGNATURES.items():
            try:
                fn = getattr(self._dll, name)
            except AttributeError:
                missing.append(name)
                continue
            fn.restype = restype
            fn.argtypes = argtypes
            setattr(self, name, fn)
        if "ft_abi_version" in missing:
            raise LibraryNotFoundError(f"{self.path} is not a fracterra library (no ft_abi_version). {HOW_TO_FIX}")
        abi = self.ft_abi_version()
        self.abi_major, self.abi_minor = abi >> 16, abi & 0xFFFF
        if self.abi_major != ABI_MAJOR:
            raise LibraryNotFoundError(
                f"{self.path} has ABI version {self.abi_major}.{self.abi_minor}; this add-on needs "
                f"{ABI_MAJOR}.x. {HOW_TO_FIX}")
        if missing:
            raise LibraryNotFoundError(
                f"{self.path} lacks {', '.join(missing)} (an older build?). {HOW_TO_FIX}")
        self.version = self.ft_version_string().decode()
        init = TerrainParams()
        self.ft_terrain_params_init(ctypes.byref(init))
        if init.struct_size != ctypes.sizeof(TerrainParams):
            raise LibraryNotFoundError(
                f"{self.path}: ft_terrain_params is {init.struct_size} bytes, the binding expects "
                f"{ctypes.sizeof(TerrainParams)}; rebuild the add-on and the library together.")

    def has(self, name):
        """True when the loaded library exports `name` (for optional capabilities)."""
        return hasattr(self._dll, name)

    def check(self, status):
        """Raises the FracterraError for a non-zero status, with ft_last_error()'s text."""
        if status != 0:
            message = self.ft_last_error().decode("utf-8", "replace")
            raise error_for_status(status, message or self.ft_status_name(status).decode())


_lock = threading.Lock()
_library = None


def library_path():
    """The path that will be tried: FRACTERRA_LIBRARY if set, else the bundled copy."""
    env = os.environ.get(ENV_VAR)
    return Path(env) if env else BUNDLED_PATH


def library():
    """The loaded Library; raises LibraryNotFoundError (with what to do) otherwise."""
    global _library
    with _lock:
        if _library is None:
            path = library_path()
            if not path.is_file():
                source = f"{ENV_VAR}={os.environ[ENV_VAR]}" if os.environ.get(ENV_VAR) else "the add-on folder"
                raise LibraryNotFoundError(f"libfracterra.so not found ({source}: {path} does not exist). {HOW_TO_FIX}")
            _library = Library(path)
        return _library


def status():
    """(ok, message) for user interfaces: the loaded version or why it cannot load."""
    try:
        lib = library()
    except LibraryNotFoundError as e:
        return False, str(e)
    return True, f"libfracterra {lib.version} (ABI {lib.abi_major}.{lib.abi_minor}) from {lib.path}"


def reset():
    """Forgets the loaded library so the next call searches again (tests, preferences)."""
    global _library
    with _lock:
        _library = None
