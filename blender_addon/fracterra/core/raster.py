# SPDX-License-Identifier: GPL-3.0-or-later
"""Heightfield files through the library (fracterra/raster.h): read any
raster GDAL reads (GeoTIFF, .hgt, .asc, ...) or a fracterra format, write
.png/.pgm/.npy/.tif (COG)/.exr/.raw/.r16 by extension, and refine a real DEM
from its own samples. bpy-free: the pytest suite uses it directly."""

import os
from ctypes import Structure, byref, c_double, c_int32, c_uint32, c_void_p, sizeof

from .binding import enum_values, library
from .terrain import Heightfield

NODATA = {"REFUSE": 0, "FILL": 1, "KEEP": 2}
WRITE_EXTENSIONS = (".png", ".pgm", ".npy", ".tif", ".exr", ".raw", ".r16")


class DemRefineReport(Structure):
    """ft_dem_refine_report (fracterra/raster.h)."""
    _fields_ = [
        ("struct_size", c_uint32),
        ("window_x", c_int32),
        ("window_y", c_int32),
        ("window_side", c_int32),
        ("hurst", c_double),
        ("hurst_stderr", c_double),
        ("sigma", c_double),
        ("increment_variance", c_double),
        ("hurst_measured", c_int32),
        ("sigma_measured", c_int32),
    ]


def _path(path):
    return os.fsencode(os.fspath(path))


def read_heightfield(path, nodata="REFUSE"):
    """A Heightfield (close it, or use `with`) read from `path`; `nodata` is
    REFUSE (an error naming the count), FILL (GDAL's inverse-distance fill)
    or KEEP (NaN, for refine_dem)."""
    lib = library()
    out = c_void_p()
    lib.check(lib.ft_heightfield_read(_path(path), NODATA[nodata], byref(out)))
    return Heightfield(out)


def write_heightfield(hf, path):
    """Writes `hf` to `path` in the format of its extension (WRITE_EXTENSIONS), atomically."""
    lib = library()
    lib.check(lib.ft_heightfield_write(hf.handle, _path(path)))


def refine_dem(dem, levels_added=2, hurst=None, sigma=None, seed=1, additions=False, threads=0):
    """(Heightfield, report dict): `dem` refined by `levels_added` levels from a
    (2^m + 1)^2 window of its own samples; hurst/sigma None are measured on it."""
    lib = library()
    p = lib.dem_refine_params_type()  # laid out from the library's description
    lib.ft_dem_refine_params_init(byref(p))
    p.levels_added = levels_added
    p.hurst = -1.0 if hurst is None else hurst
    p.sigma = -1.0 if sigma is None else sigma
    p.seed = seed
    p.method = enum_values("dem_refine", "method")["ADDITIONS" if additions else "MIDPOINT"]
    p.threads = threads
    report = DemRefineReport(struct_size=sizeof(DemRefineReport))
    out = c_void_p()
    lib.check(lib.ft_dem_refine(dem.handle, byref(p), byref(out), byref(report)))
    return Heightfield(out), {name: getattr(report, name) for name, _ in DemRefineReport._fields_[1:]}
