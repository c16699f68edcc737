# SPDX-License-Identifier: GPL-3.0-or-later
"""fracterra for Python: fractal terrains, erosion and their measures as numpy
arrays, on the same native library (and the same ctypes binding) as the
Blender add-on and the `fracterra` command-line tool.

    import fracterra as ft
    z = ft.terrain(method="midpoint", levels=10, hurst=0.8, seed=7)   # numpy float32, world size attached
    e, maps = ft.erode(z, preset="land")
    print(ft.analyze(e))                                                # H, D, drainage statistics
    ft.save(e, "e.tif")

The keyword arguments of terrain() and erode() are the library's parameter
tables (help(ft.terrain) lists them with defaults and ranges). Errors are
fracterra.FracterraError subclasses carrying the library's message.
"""

import platform as _platform
import sys as _sys

# The wheel carries libfracterra for one platform; say so at import rather
# than failing later inside ctypes.
_SUPPORTED = {("linux", "x86_64"): "libfracterra.so"}
_here = (_sys.platform, _platform.machine().lower())
if _here not in _SUPPORTED:
    raise ImportError(
        f"fracterra: this wheel holds the native library for linux-x86_64 only; this Python runs on "
        f"{_sys.platform}-{_platform.machine()} (build the library and the package from source there: "
        f"see the project's README)")

from .core.errors import (CancelledError, FracterraError, InvalidArgumentError,  # noqa: E402
                          LibraryNotFoundError, TooLargeError, UnsupportedError)
from .api import Terrain, analyze, erode, load, save, splat, terrain, version  # noqa: E402

__all__ = ["Terrain", "terrain", "erode", "analyze", "save", "load", "splat", "version", "FracterraError",
           "InvalidArgumentError", "TooLargeError", "CancelledError", "UnsupportedError", "LibraryNotFoundError"]
try:
    from importlib.metadata import version as _dist_version
    __version__ = _dist_version("fracterra")
except Exception:  # run from the source tree, not installed
    __version__ = "0+source"
