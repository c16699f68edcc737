# SPDX-License-Identifier: GPL-3.0-or-later
"""The bpy-free part of the fracterra add-on: the ctypes binding of
libfracterra.so, the parameter definitions and grid-mesh arrays. Importable
without Blender (the pytest suite uses it directly)."""

from . import params
from .errors import (CancelledError, FracterraError, InvalidArgumentError, LibraryNotFoundError,
                     TooLargeError, UnsupportedError)
from .grid import grid_arrays, grid_size, vertices
from .binding import ENV_VAR, library, status
from .pipeline import build_terrain, build_terrain_rivers
from .polylines import Polylines, coastline, generate_polylines, hurst_of_heightfield
from .terrain import Heightfield, generate_profile, generate_terrain, mandelbrot_level_height, terrain_side

__all__ = ["params", "FracterraError", "LibraryNotFoundError", "InvalidArgumentError", "CancelledError",
           "TooLargeError", "UnsupportedError", "grid_arrays", "grid_size", "vertices", "ENV_VAR",
           "library", "status", "build_terrain", "build_terrain_rivers", "Heightfield", "generate_profile", "generate_terrain", "mandelbrot_level_height", "terrain_side",
           "Polylines", "generate_polylines", "coastline", "hurst_of_heightfield"]
