# SPDX-License-Identifier: GPL-3.0-or-later
"""fracterra for Python: fractal terrains, erosion and their measures as numpy
arrays, on the same native library (and the same ctypes binding) as the
Blender add-on and the `fracterra` command-line tool.

    import fracterra as ft
    z = ft.terrain(method="midpoint", levels=10, hurst=0.8, seed=7)   # numpy float32 with its world
    e, maps = ft.erode(z, "rugged_mountains")       # = ft.terrain(..., erode="rugged_mountains"), bit for bit
    print(ft.analyze(e))                            # H, D, drainage statistics
    ft.rivers(e).to_geojson("rivers.geojson")
    ft.save(e, "e.tif")

terrain() is the library's pipeline (ft_terrain_build), as `fracterra
terrain` and the Blender add-on run it; erode() and rivers() are its stages
on a terrain already made. The keyword arguments are the library's parameter
tables (help(ft.terrain) lists them with defaults, units and ranges). Errors
are fracterra.FracterraError subclasses carrying the library's message.
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
from .arrays import Terrain  # noqa: E402
from .api import analyze, load, save, splat, version  # noqa: E402
from .meshes import fractalize  # noqa: E402
from .pipeline import Build, erode, rivers, terrain, window  # noqa: E402
from .planets import planet  # noqa: E402
from .polylines import Lines, coastline, fpl_study, polyline  # noqa: E402
from .rivers import Rivers  # noqa: E402
from .scenes import clouds, pov_scene, render  # noqa: E402


def __getattr__(name):
    """ft.tiles, imported on first use (PEP 562): imported here eagerly, `python3 -m fracterra.tiles`
    (the Dask driver) would find its own module already loaded and warn, in the driver and in every
    worker. The module is callable: ft.tiles(out_dir, ...) writes a tile set on this machine."""
    if name == "tiles":
        import importlib
        return importlib.import_module(__name__ + ".tiles")  # `from . import` would ask __getattr__ again
    raise AttributeError(f"module 'fracterra' has no attribute {name!r}")


__all__ = ["Terrain", "Build", "Rivers", "Lines", "terrain", "window", "erode", "rivers", "analyze", "polyline",
           "fpl_study", "coastline", "clouds", "planet", "pov_scene", "render", "fractalize", "tiles", "splat", "save",
           "load", "version", "FracterraError", "InvalidArgumentError", "TooLargeError", "CancelledError",
           "UnsupportedError", "LibraryNotFoundError"]


def _annotate():
    """Signatures and docs from the library's tables (when it loads; else the calls will say why)."""
    from .core.errors import LibraryNotFoundError as _Missing
    from . import meshes, pipeline, planets, polylines, scenes
    try:
        for module in (pipeline, polylines, planets, scenes, meshes):
            module._annotate()
    except _Missing:
        pass


_annotate()
try:
    from importlib.metadata import version as _dist_version
    __version__ = _dist_version("fracterra")
except Exception:  # run from the source tree, not installed
    __version__ = "0+source"
