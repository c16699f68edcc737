# SPDX-License-Identifier: GPL-3.0-or-later
"""Finding and loading libfracterra.so (fracterra.dll on Windows), and the ctypes signature of every symbol.

Search order: the path in the FRACTERRA_LIBRARY environment variable (when
set, it is the only candidate: an explicit choice must not silently fall back),
then the copy bundled in the add-on's `lib/` folder (the legacy zip, the Python
wheel), then the one in the fracterra_native wheel that Blender 4.2+ installs
from the extension (its site-packages). The library is loaded
on first use, so the add-on registers even when it is missing and can say
what to do. A library whose ABI major version differs is refused.
"""

import ctypes
import importlib.util
import os
import platform
import sys
import threading
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char_p, c_double, c_float, c_int32, c_int64,
                    c_size_t, c_uint16, c_uint32, c_uint64, c_void_p)
from pathlib import Path

from .errors import LibraryNotFoundError, error_for_status
from .rows import FLAG_DATA, FLAG_MAX_EXCLUSIVE, FLAG_MIN_EXCLUSIVE, FLAG_STRUCT_SIZE, FLAG_ZERO_IS_AUTO  # noqa: F401
from . import rows  # noqa: F401  (binding.rows: the one reader)
from .rows import FT_PARAM, enum_item, row_from_info  # noqa: F401

ABI_MAJOR = 2
ABI_MINOR_MIN = 28  # what each minor added: CHANGES.md, "ABI history"
ENV_VAR = "FRACTERRA_LIBRARY"
# The library of each platform the add-on zip can carry one for (docs/windows.md).
LIBRARY_NAMES = {("linux", "x86_64"): "libfracterra.so", ("win32", "amd64"): "fracterra.dll"}
PLATFORM = (sys.platform, platform.machine().lower())
LIBRARY_NAME = LIBRARY_NAMES.get(PLATFORM, "libfracterra.so")
BUNDLED_PATH = Path(__file__).resolve().parent.parent / "lib" / LIBRARY_NAME
WHEEL_PACKAGE = "fracterra_native"  # blender_addon/native_wheel

HOW_TO_FIX = (
    "Install the extension of this platform (Blender 4.2+: built by `cmake --build build --target "
    "fracterra_extensions`) or the add-on zip built by `cmake --build build --target fracterra_blender_addon` "
    f"(it bundles lib/{LIBRARY_NAME}), or set the environment variable "
    f"{ENV_VAR} to the full path of {LIBRARY_NAME} before starting Blender."
)


def unsupported_platform():
    """Why this platform has no library ("" where it has one): the zip carries Linux and Windows x64 only."""
    if PLATFORM in LIBRARY_NAMES:
        return ""
    return (f"fracterra has no library for this platform ({sys.platform}, {platform.machine()}): the add-on "
            "carries lib/libfracterra.so for x86-64 Linux and lib/fracterra.dll for x64 Windows only. "
            f"Build the library for this platform and set {ENV_VAR} to its path.")

# ft_progress_fn: int32_t (*)(void* user, double fraction); non-zero cancels.
PROGRESS_FN = CFUNCTYPE(c_int32, c_void_p, c_double)


class ParamEnumItem(Structure):
    """ft_param_enum_item (fracterra/params.h)."""
    _fields_ = [("value", c_int32), ("name", c_char_p), ("label", c_char_p), ("doc", c_char_p)]


class ParamInfo(Structure):
    """ft_param_info (fracterra/params.h): the one struct written out by hand here, since
    it is how the library describes all the others. Checked against its struct_size."""
    _fields_ = [
        ("struct_size", c_uint32), ("type", c_int32), ("name", c_char_p), ("offset", c_uint32),
        ("size", c_uint32), ("count", c_int32), ("flags", c_uint32), ("since", c_uint32),
        ("element_type", c_int32), ("element_kind", c_int32), ("default_value", c_double),
        ("hard_min", c_double), ("hard_max", c_double), ("soft_min", c_double), ("soft_max", c_double),
        ("unit", c_char_p), ("label", c_char_p), ("doc", c_char_p), ("methods", c_uint64),
        ("enum_count", c_int32), ("enum_items", POINTER(ParamEnumItem)),
    ]


# fracterra/params.h: the described structs (their rows are read by rows.py, the one reader).
PARAMS_KINDS = {"terrain": 0, "profile": 1, "polyline": 2, "fractalize": 3, "pov_scene": 4, "pov_sweep": 5,
                "hurst": 6, "clouds": 7, "dem_refine": 8, "erosion": 9, "build": 10, "hydrology": 11,
                "planet": 12, "splat": 13}
_SCALAR_CTYPES = {"uint32": c_uint32, "int32": c_int32, "int64": c_int64, "uint64": c_uint64, "float": c_float,
                  "double": c_double, "bool": c_int32, "enum": c_int32, "string": c_char_p,
                  "callback": PROGRESS_FN}
_ELEMENT_CTYPES = {"float": POINTER(c_float), "double": POINTER(c_double), "opaque": c_void_p}


def _ctype_of(row, struct_types):
    if row["type"] == "pointer":
        if row["element_kind"] >= 0:
            return POINTER(struct_types[row["element_kind"]])
        return _ELEMENT_CTYPES[row["element_type"]]
    t = _SCALAR_CTYPES[row["type"]]
    return t * row["count"] if row["count"] > 1 else t


def structure_from_rows(name, rows, size, struct_types=None):
    """A ctypes Structure laid out from the library's description, checked field by field:
    every offset and the total size must come out as the library says."""
    fields = [(r["name"], _ctype_of(r, struct_types or {})) for r in rows]
    cls = type(name, (Structure,), {"_fields_": fields, "__doc__": f"{name}, as the library describes it"})
    for r in rows:
        got = getattr(cls, r["name"])
        if got.offset != r["offset"] or got.size != r["size"]:
            raise LibraryNotFoundError(f"{name}.{r['name']}: the library says offset {r['offset']}, size "
                                       f"{r['size']}; ctypes lays it at {got.offset}, size {got.size}")
    if ctypes.sizeof(cls) != size:
        raise LibraryNotFoundError(f"{name}: the library says {size} bytes, ctypes makes {ctypes.sizeof(cls)}")
    return cls


class _Described:
    """A SIGNATURES placeholder for POINTER(the struct of this kind built at load time)."""

    def __init__(self, kind):
        self.kind = kind


class PolylineStats(Structure):
    """ft_polyline_stats (fracterra/polyline.h)."""
    _fields_ = [
        ("struct_size", c_uint32),
        ("reserved0", c_int32),
        ("line_count", c_int64),
        ("vertex_count", c_int64),
        ("eta", c_double),
        ("chi", c_double),
        ("gamma", c_double),
        ("length", c_double),
        ("mass_dimension", c_double),
        ("box_dimension", c_double),
        ("box_dimension_std_error", c_double),
        ("box_min_size", c_double),
        ("box_max_size", c_double),
        ("box_sizes", c_int32),
        ("reserved1", c_int32),
    ]


class HurstResult(Structure):
    """ft_hurst_result (fracterra/analysis.h)."""
    _fields_ = [
        ("struct_size", c_uint32),
        ("method", c_int32),
        ("transects", c_int32),
        ("points", c_int32),
        ("hurst", c_double),
        ("dimension", c_double),
        ("std_error", c_double),
        ("band_lo", c_double),
        ("band_hi", c_double),
        ("band_is_frequency", c_int32),
        ("auto_reason", c_int32),
        ("auto_reason_text", c_char_p),
    ]


class DrainageStats(Structure):
    """ft_drainage_stats (fracterra/erosion.h)."""
    _fields_ = [("hack_h", c_double), ("hack_h_stderr", c_double), ("theta", c_double),
                ("theta_stderr", c_double), ("hack_bins", c_int32), ("theta_bins", c_int32)]


class TerrainWorld(Structure):
    """ft_terrain_world (fracterra/pipeline.h, ABI 2.27): whether a terrain tiles, and its own sea."""
    _fields_ = [("struct_size", c_uint32), ("period_overlap", c_int32), ("sea_level", c_double)]


class FplStudyRow(Structure):
    """ft_fpl_study_row (fracterra/polyline.h, ABI 2.27)."""
    _fields_ = [("spread", c_double), ("depth", c_int32), ("count", c_int32)] + [
        (name, c_double) for name in ("eta_mean", "eta_se", "chi_mean", "chi_se", "gamma_mean", "gamma_se",
                                      "mass_dimension_mean", "mass_dimension_se", "box_dimension_mean",
                                      "box_dimension_se", "paper_eta", "paper_chi", "paper_gamma", "paper_dimension")]


class NetworkMeasures(Structure):
    """ft_network_measures (fracterra/hydrology.h, ABI 2.27)."""
    _fields_ = [("struct_size", c_uint32), ("horton_orders", c_int32), ("horton_fitted_orders", c_int32),
                ("hack_points", c_int32)] + [
        (n, c_double) for n in ("bifurcation_ratio", "bifurcation_ratio_stderr", "length_ratio", "length_ratio_stderr",
                                "total_length", "land_area", "drainage_density", "hack_h", "hack_h_stderr")] + [
        ("segments", c_int64), ("lakes", c_int64), ("vertices", c_int64), ("ends", c_int32 * 5),
        ("reserved0", c_int32), ("streams", c_int64 * 32), ("mean_length", c_double * 32)]


class PovSceneLines(Structure):
    """ft_pov_scene_lines (fracterra/povray.h): an array of them is the data that
    ft_pov_scene_params.lines points to (described as an opaque pointer)."""
    _fields_ = [("lines", c_void_p), ("kind", c_int32), ("radius", c_double)]


class PovLight(Structure):
    """ft_pov_light (fracterra/povray.h): an array of them is the data that
    ft_pov_scene_params.lights points to."""
    _fields_ = [("kind", c_int32), ("color", c_double * 3), ("power", c_double), ("location", c_double * 3),
                ("direction", c_double * 3), ("spot_size_deg", c_double), ("spot_blend", c_double),
                ("spot_cos_power", c_double), ("area_u", c_double * 3), ("area_v", c_double * 3),
                ("area_ellipse", c_int32), ("shadows", c_int32)]


class PovMaterial(Structure):
    """ft_pov_material (fracterra/povray.h)."""
    _fields_ = [("color", c_double * 3), ("emission", c_double * 3), ("roughness", c_double),
                ("specular", c_double), ("water", c_int32)]


class PovSceneMesh(Structure):
    """ft_pov_scene_mesh (fracterra/povray.h): an array of them is the data that
    ft_pov_scene_params.meshes points to."""
    _fields_ = [("mesh", c_void_p), ("material", PovMaterial), ("smooth", c_int32)]


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
    "ft_params_describe": (c_int32, [c_int32, POINTER(c_char_p), POINTER(c_uint32), POINTER(c_int32)]),
    "ft_params_field": (c_int32, [c_int32, c_int32, POINTER(POINTER(ParamInfo))]),
    "ft_version_string": (c_char_p, []),
    "ft_last_error": (c_char_p, []),
    "ft_status_name": (c_char_p, [c_int32]),
    "ft_build_features": (c_char_p, []),
    "ft_has_feature": (c_int32, [c_char_p]),
    "ft_heightfield_formats": (c_char_p, []),
    "ft_memory_cap": (c_uint64, []),
    "ft_set_memory_cap": (None, [c_uint64]),
    "ft_heightfield_create": (c_int32, [c_int32, c_int32, _F32P, POINTER(_HF)]),
    "ft_heightfield_width": (c_int32, [_HF]),
    "ft_heightfield_height": (c_int32, [_HF]),
    "ft_heightfield_data": (_F32P, [_HF]),
    "ft_heightfield_data_mut": (_F32P, [_HF]),
    "ft_heightfield_copy": (c_int32, [_HF, _F32P, c_size_t]),
    "ft_heightfield_stats": (c_int32, [_HF, _F64P, _F64P, _F64P, _F64P]),
    "ft_heightfield_world_size": (c_double, [_HF]),
    "ft_heightfield_set_world_size": (c_int32, [_HF, c_double]),
    "ft_heightfield_free": (None, [_HF]),
    "ft_polylines_create": (c_int32, [_F64P, _F64P, c_int64, POINTER(c_int64), c_int64, POINTER(_PL)]),
    "ft_polylines_line_count": (c_int64, [_PL]),
    "ft_polylines_vertex_count": (c_int64, [_PL]),
    "ft_polylines_xyz": (_F64P, [_PL]),
    "ft_polylines_radii": (_F64P, [_PL]),
    "ft_polylines_offsets": (POINTER(c_int64), [_PL]),
    "ft_polylines_free": (None, [_PL]),
    "ft_terrain_params_init": (c_int32, [_Described("terrain")]),
    "ft_terrain_generate": (c_int32, [_Described("terrain"), POINTER(_HF)]),
    "ft_terrain_extent": (c_int32, [_Described("terrain"), c_int32, POINTER(c_int64), POINTER(c_int64)]),
    "ft_terrain_generate_window": (c_int32, [_Described("terrain"), c_int64, c_int64, c_int32, c_int32, POINTER(_HF)]),
    "ft_terrain_generate_window_lod": (c_int32, [_Described("terrain"), c_int32, c_int64, c_int64, c_int32, c_int32, POINTER(_HF)]),
    "ft_terrain_side": (c_int32, [c_int32]),
    "ft_mandelbrot_level_height": (c_int32, [_Described("terrain"), c_double, POINTER(c_double)]),
    "ft_profile_params_init": (c_int32, [_Described("profile")]),
    "ft_profile_generate": (c_int32, [_Described("profile"), _F32P, c_size_t]),
    "ft_profile_length": (c_int64, [c_int32]),
    "ft_polyline_params_init": (c_int32, [_Described("polyline")]),
    "ft_polyline_generate": (c_int32, [_Described("polyline"), POINTER(_PL)]),
    "ft_polyline_measure": (c_int32, [_PL, POINTER(PolylineStats)]),
    "ft_hurst_params_init": (c_int32, [_Described("hurst")]),
    "ft_hurst_profile": (c_int32, [_F32P, c_size_t, _Described("hurst"), POINTER(HurstResult)]),
    "ft_hurst_heightfield": (c_int32, [_HF, _Described("hurst"), POINTER(HurstResult)]),
    "ft_coastline": (c_int32, [_HF, c_double, c_int32, POINTER(_PL)]),
    "ft_level_curves": (c_int32, [_HF, POINTER(c_double), c_size_t, POINTER(_PL)]),
    "ft_clouds_params_init": (c_int32, [_Described("clouds")]),
    "ft_clouds": (c_int32, [_HF, _Described("clouds"), POINTER(ctypes.c_uint16), c_size_t]),
    "ft_clouds_write_png": (c_int32, [_HF, _Described("clouds"), c_char_p]),
    "ft_pov_scene_params_init": (c_int32, [_Described("pov_scene")]),
    "ft_pov_write_scene": (c_int32, [_Described("pov_scene"), c_char_p]),
    "ft_pov_sweep_params_init": (c_int32, [_Described("pov_sweep")]),
    "ft_pov_write_sweeps": (c_int32, [_PL, _Described("pov_sweep"), c_char_p, c_char_p]),
    "ft_pov_render": (c_int32, [c_char_p, c_char_p, c_int32, c_int32, c_double]),
    "ft_mesh_create": (c_int32, [_F32P, c_int64, _I32P, c_int64, _I32P, _I32P, _F32P, c_int64,
                                 POINTER(c_void_p)]),
    "ft_mesh_set_corners": (c_int32, [c_void_p, _I32P, _F32P, c_int64]),
    "ft_mesh_vertex_count": (c_int64, [c_void_p]),
    "ft_mesh_positions": (_F32P, [c_void_p]),
    "ft_mesh_face_count": (c_int64, [c_void_p]),
    "ft_mesh_face_sizes": (_I32P, [c_void_p]),
    "ft_mesh_face_index_count": (c_int64, [c_void_p]),
    "ft_mesh_face_indices": (_I32P, [c_void_p]),
    "ft_mesh_free": (None, [c_void_p]),
    "ft_fractalize_params_init": (c_int32, [_Described("fractalize")]),
    "ft_fractalize": (c_int32, [c_void_p, _Described("fractalize"), POINTER(c_void_p)]),
    "ft_grid_counts_get": (c_int32, [c_int32, c_int32, POINTER(GridCounts)]),
    "ft_grid_vertices": (c_int32, [_HF, c_double, c_double, c_double, _F32P, c_size_t]),
    "ft_grid_heights": (c_int32, [_HF, c_double, _F32P, c_size_t, c_size_t]),
    "ft_grid_topology": (c_int32, [c_int32, c_int32, _I32P, _I32P, c_size_t, _I32P, c_size_t,
                                   _I32P, _I32P, c_size_t]),
    "ft_grid_uvs": (c_int32, [c_int32, c_int32, _F32P, c_size_t]),
    # erosion.h (ABI 2.1; its params described from 2.6): the maps come back as FT_MAP_COUNT handles.
    "ft_erosion_params_init": (c_int32, [_Described("erosion")]),
    "ft_erosion_preset": (c_int32, [c_char_p, _Described("erosion")]),
    "ft_erosion_preset_fitted": (c_int32, [c_char_p, _HF, _Described("erosion")]),
    "ft_erode": (c_int32, [_HF, _Described("erosion"), POINTER(_HF), POINTER(_HF)]),
    "ft_drainage_statistics": (c_int32, [_HF, c_int32, c_double, POINTER(DrainageStats)]),
    # splat.h (ABI 2.19): splat (weight) and colour maps by layer rules (ft_splat_params, described).
    "ft_splat_params_init": (c_int32, [_Described("splat")]),
    "ft_splat_default_layers": (c_int32, [_Described("splat"), c_int32, POINTER(c_int32)]),
    "ft_splat_weights": (c_int32, [_HF, _HF, _HF, _Described("splat"), c_int32, c_int32, POINTER(c_uint16),
                                   c_size_t]),
    "ft_splat_colors": (c_int32, [_HF, _HF, _HF, _Described("splat"), c_int32, _F32P, c_size_t]),
    # (ABI 2.25) the colours as Blender's colour attribute takes them, with progress and cancel.
    "ft_splat_colors_linear_rgba": (c_int32, [_HF, _HF, _HF, _Described("splat"), c_int32, c_int32, PROGRESS_FN,
                                              c_void_p, _F32P, c_size_t]),
    # (ABI 2.22) a rules JSON file read and checked by the library (core/splat.py).
    "ft_splat_rules_read": (c_int32, [c_char_p, POINTER(c_void_p)]),
    "ft_splat_rules_layers": (c_int32, [c_void_p, _Described("splat"), c_int32, POINTER(c_int32)]),
    "ft_splat_rules_free": (None, [c_void_p]),
    # pipeline.h (ABI 2.13): the whole terrain in one call; maps NULL or FT_MAP_COUNT handles.
    "ft_build_params_init": (c_int32, [_Described("build")]),
    "ft_terrain_build": (c_int32, [_Described("build"), POINTER(_HF), POINTER(_HF)]),
    # (ABI 2.20) with the rivers stage: the network's handle (core/rivers.py).
    "ft_terrain_build_rivers": (c_int32, [_Described("build"), POINTER(_HF), POINTER(_HF), POINTER(c_void_p)]),
    # (ABI 2.26) a window of what ft_terrain_build makes, heights and maps, bit-identical to the whole's.
    "ft_terrain_build_window": (c_int32, [_Described("build"), c_int64, c_int64, c_int32, c_int32, POINTER(_HF), POINTER(_HF)]),
    # (ABI 2.27) the build's world, and the erode and rivers stages on a terrain already made.
    "ft_terrain_world_init": (c_int32, [POINTER(TerrainWorld)]),
    "ft_terrain_build_world": (c_int32, [_Described("build"), POINTER(_HF), POINTER(_HF), POINTER(c_void_p),
                                         POINTER(TerrainWorld)]),
    "ft_terrain_erode": (c_int32, [_Described("build"), _HF, POINTER(TerrainWorld), POINTER(_HF), POINTER(_HF)]),
    "ft_terrain_rivers": (c_int32, [_Described("build"), _HF, POINTER(TerrainWorld), POINTER(c_void_p)]),
    "ft_river_network_write": (c_int32, [c_void_p, _HF, c_char_p, c_int32]),
    "ft_river_network_measures": (c_int32, [c_void_p, c_void_p]),
    "ft_fpl_study": (c_int32, [c_int32, _F64P, c_int32, _I32P, c_int32, c_int32, c_uint64, c_int32, PROGRESS_FN,
                               c_void_p, c_void_p, c_int64]),
    "ft_hurst_heightfield_points": (c_int32, [_HF, _Described("hurst"), POINTER(HurstResult), _F64P, _F64P, c_int64,
                                              POINTER(c_int64)]),
    # hydrology.h (ABI 2.15): rivers, lakes and the sea; the segment and lake structs as raw memory.
    "ft_hydrology_params_init": (c_int32, [_Described("hydrology")]),
    "ft_rivers_extract": (c_int32, [_HF, _Described("hydrology"), POINTER(c_void_p)]),
    "ft_river_network_free": (None, [c_void_p]),
    "ft_river_network_segment_count": (c_int32, [c_void_p]),
    "ft_river_network_lake_count": (c_int32, [c_void_p]),
    "ft_river_network_grid": (c_int32, [c_void_p, _I32P, _I32P]),
    "ft_river_network_polylines": (c_int32, [c_void_p, POINTER(c_void_p)]),
    "ft_river_network_vertex_values": (c_int32, [c_void_p, c_int32, POINTER(c_double), c_int64]),
    "ft_river_network_segments": (c_int32, [c_void_p, c_void_p, c_int32]),
    "ft_river_network_lakes": (c_int32, [c_void_p, c_void_p, c_int32]),
    "ft_river_network_lake_rings": (c_int32, [c_void_p, POINTER(c_void_p)]),
    # (ABI 2.27) the minimum water depth it was traced with (0 given: 1% of the relief).
    "ft_river_network_min_depth": (c_int32, [c_void_p, _F64P]),
    "ft_river_network_water_mask": (c_int32, [c_void_p, POINTER(c_int32), c_int64]),
    # (ABI 2.28) the rivers as drawn: cut where a ribbon would reach into a lake.
    "ft_river_network_ribbon_lines": (c_int32, [c_void_p, POINTER(c_void_p)]),
    "ft_rivers_carve": (c_int32, [_HF, c_void_p, POINTER(_HF)]),
    # planet.h (ABI 2.18): fractal planets; heightfields, or meshes into caller-allocated arrays.
    "ft_planet_params_init": (c_int32, [_Described("planet")]),
    "ft_planet_face": (c_int32, [_Described("planet"), c_int32, c_int32, c_int64, c_int64, c_int32, c_int32,
                                 POINTER(_HF)]),
    "ft_planet_equirect": (c_int32, [_Described("planet"), c_int32, c_int32, POINTER(_HF)]),
    "ft_planet_heights": (c_int32, [_Described("planet"), _F64P, c_int64, _F32P]),
    "ft_planet_sea_height": (c_int32, [_Described("planet"), _F64P]),
    "ft_planet_mesh_counts": (c_int32, [c_int32, POINTER(c_int64), POINTER(c_int64)]),
    # (ABI 2.23) the icosphere and the angular power spectrum.
    "ft_planet_icosphere_counts": (c_int32, [c_int32, POINTER(c_int64), POINTER(c_int64)]),
    "ft_planet_icosphere": (c_int32, [_Described("planet"), c_int32, c_double, _F32P, c_size_t, _I32P, c_size_t,
                                      _F32P, c_size_t]),
    "ft_planet_power_spectrum": (c_int32, [_Described("planet"), c_int32, _F64P, c_size_t]),
    "ft_planet_spectrum_hurst": (c_int32, [_Described("planet"), c_int32, c_int32, _F64P, _F64P]),
    "ft_planet_mesh": (c_int32, [_Described("planet"), c_int32, c_double, _F32P, c_size_t, _I32P, c_size_t,
                                 _F32P, c_size_t]),
    # raster.h (ABI 1.4); its structs are in core/raster.py.
    "ft_heightfield_read": (c_int32, [c_char_p, c_int32, POINTER(_HF)]),
    "ft_heightfield_write": (c_int32, [_HF, c_char_p]),
    "ft_dem_refine_params_init": (None, [_Described("dem_refine")]),
    "ft_dem_refine": (c_int32, [_HF, _Described("dem_refine"), POINTER(_HF), c_void_p]),
    # tiles.h (ABI 2.4; journals and per-tile ranges 2.10): the tile sets core/tiles.py drives.
    "ft_tileset_open": (c_int32, [c_void_p, c_int32, c_int32, c_char_p, POINTER(c_void_p)]),
    "ft_tileset_open_deferred": (c_int32, [c_void_p, c_int32, c_int32, c_char_p, POINTER(c_void_p),
                                           POINTER(c_int32)]),
    "ft_tileset_set_height_range": (c_int32, [c_void_p, c_double, c_double]),
    "ft_tile_height_range": (c_int32, [c_void_p, c_int32, c_int32, c_int32, POINTER(c_double), POINTER(c_double)]),
    "ft_tileset_free": (None, [c_void_p]),
    "ft_tileset_grid": (c_int32, [c_void_p, POINTER(c_int32), POINTER(c_int32)]),
    "ft_tileset_height_range": (c_int32, [c_void_p, POINTER(c_double), POINTER(c_double)]),
    "ft_tileset_tile_done": (c_int32, [c_void_p, c_int32, c_int32, POINTER(c_int32)]),
    "ft_tileset_record": (c_int32, [c_void_p, c_int32, c_int32, c_uint32]),
    "ft_tileset_finish": (c_int32, [c_void_p]),
    "ft_tile_write": (c_int32, [c_void_p, c_int32, c_int32, c_double, c_double, c_char_p, c_int32, c_int32,
                                POINTER(c_uint32)]),
    "ft_tileset_extent": (c_int32, [c_char_p, c_int32, POINTER(c_int64), POINTER(c_int64)]),
    "ft_tileset_read_window": (c_int32, [c_char_p, c_int32, c_int64, c_int64, c_int32, c_int32,
                                         POINTER(c_void_p)]),
    # tiles.h (ABI 2.26): tile sets of built (landformed, eroded) terrains and their maps.
    "ft_tileset_open_build": (c_int32, [_Described("build"), c_int32, c_int32, c_int32, c_int32, c_char_p,
                                        POINTER(c_void_p), POINTER(c_int32)]),
    "ft_tile_build_range": (c_int32, [_Described("build"), c_int32, c_int32, c_int32, c_char_p, c_int32, c_int32,
                                      POINTER(c_double), POINTER(c_double)]),
    "ft_tile_write_build": (c_int32, [_Described("build"), c_int32, c_int32, c_int32, c_double, c_double, c_char_p,
                                      c_int32, c_int32, POINTER(c_uint32), c_int32]),
    "ft_tileset_record_tile": (c_int32, [c_void_p, c_int32, c_int32, POINTER(c_uint32), c_int32]),
    "ft_tileset_read_map_window": (c_int32, [c_char_p, c_int32, c_int32, c_int64, c_int64, c_int32, c_int32,
                                             POINTER(c_void_p)]),
    "ft_tileset_cut_for_engine": (c_int32, [c_char_p, c_char_p, c_int32, c_int32, c_char_p]),
    "ft_tileset_window_colors": (c_int32, [c_char_p, c_int32, c_int64, c_int64, c_int32, c_int32,
                                           _Described("splat"), c_int32, POINTER(c_float), c_size_t]),
    # analysis.h (ABI 2.4): H of a surface from per-window increment sums.
    "ft_increment_lags": (c_int32, [c_void_p, c_int64, c_int64, POINTER(c_int64), c_size_t, POINTER(c_size_t)]),
    "ft_increment_sums": (c_int32, [c_void_p, c_void_p, c_int64, c_int64, c_int64, c_int64, POINTER(c_double),
                                    POINTER(c_double), c_size_t]),
    "ft_hurst_from_increment_sums": (c_int32, [c_void_p, c_int64, c_int64, POINTER(c_double), POINTER(c_double),
                                               c_size_t, c_void_p]),
}


class Library:
    """The loaded library: attribute access gives the declared functions."""

    def __init__(self, path):
        self.path = Path(path)
        try:
            self._dll = ctypes.CDLL(str(self.path))
        except OSError as e:
            raise LibraryNotFoundError(f"cannot load {self.path}: {e}. {HOW_TO_FIX}") from None
        missing = self._bind({k: v for k, v in SIGNATURES.items()
                              if not any(isinstance(a, _Described) for a in v[1])})
        if "ft_abi_version" in missing:
            raise LibraryNotFoundError(f"{self.path} is not a fracterra library (no ft_abi_version). {HOW_TO_FIX}")
        abi = self.ft_abi_version()
        self.abi_major, self.abi_minor = abi >> 16, abi & 0xFFFF
        if self.abi_major != ABI_MAJOR or self.abi_minor < ABI_MINOR_MIN:
            raise LibraryNotFoundError(
                f"{self.path} has ABI version {self.abi_major}.{self.abi_minor}; this add-on needs "
                f"{ABI_MAJOR}.{ABI_MINOR_MIN} or a later {ABI_MAJOR}.x. {HOW_TO_FIX}")
        if missing:
            raise LibraryNotFoundError(
                f"{self.path} lacks {', '.join(missing)} (an older build?). {HOW_TO_FIX}")
        self.version = self.ft_version_string().decode()
        # The params structs as the library describes them: their layout cannot drift.
        self.param_rows, self.struct_types = {}, {}
        described = {kind: self.describe(kind) for kind in PARAMS_KINDS.values()}
        # A struct that points to another (ft_build_params to ft_hydrology_params)
        # is made after it, whatever their kind numbers.
        todo = list(PARAMS_KINDS.items())
        while todo:
            ready = [(n, k) for n, k in todo
                     if all(r["element_kind"] < 0 or r["element_kind"] in self.struct_types or r["type"] != "pointer"
                            for r in described[k][2])]
            if not ready:
                raise LibraryNotFoundError(f"{self.path}: params structs point to each other in a circle")
            for kind_name, kind in ready:
                struct_name, size, rows = described[kind]
                self.param_rows[kind_name] = rows
                self.struct_types[kind] = structure_from_rows(struct_name, rows, size, self.struct_types)
                todo.remove((kind_name, kind))
        self._bind({name: (restype, [POINTER(self.struct_types[PARAMS_KINDS[a.kind]])
                                     if isinstance(a, _Described) else a for a in argtypes])
                    for name, (restype, argtypes) in SIGNATURES.items()
                    if any(isinstance(a, _Described) for a in argtypes)})
        # Every params struct is the library's own size (a later 2.x may have appended
        # fields), so the library never reads or writes past the end of what we pass.
        for kind_name, kind in PARAMS_KINDS.items():
            setattr(self, f"{kind_name}_params_type", self.struct_types[kind])

    def _bind(self, signatures):
        """Declares restype and argtypes of each symbol; returns the names the library lacks."""
        missing = []
        for name, (restype, argtypes) in signatures.items():
            try:
                fn = getattr(self._dll, name)
            except AttributeError:
                missing.append(name)
                continue
            fn.restype = restype
            fn.argtypes = argtypes
            setattr(self, name, fn)
        return missing

    def describe(self, kind):
        """(struct name, size, [field dicts]) of params struct `kind` (fracterra/params.h)."""
        name, size, count = c_char_p(), c_uint32(), c_int32()
        self.check(self.ft_params_describe(kind, ctypes.byref(name), ctypes.byref(size), ctypes.byref(count)))
        rows = []
        for i in range(count.value):
            info = POINTER(ParamInfo)()
            self.check(self.ft_params_field(kind, i, ctypes.byref(info)))
            if info.contents.struct_size < ctypes.sizeof(ParamInfo):
                raise LibraryNotFoundError(f"{self.path}: ft_param_info is {info.contents.struct_size} bytes, "
                                           f"the binding reads {ctypes.sizeof(ParamInfo)}. {HOW_TO_FIX}")
            rows.append(row_from_info(info.contents))
        return name.value.decode(), size.value, rows

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


def wheel_library_path():
    """The library in the installed fracterra_native wheel (found, not imported), or None."""
    try:
        spec = importlib.util.find_spec(WHEEL_PACKAGE)
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.origin:
        return None
    return Path(spec.origin).resolve().parent / "lib" / LIBRARY_NAME


def library_path():
    """The path that will be tried: FRACTERRA_LIBRARY if set, else the bundled copy,
    else the extension's wheel's (the bundled path when neither exists, for the message)."""
    env = os.environ.get(ENV_VAR)
    if env:
        return Path(env)
    if BUNDLED_PATH.is_file():
        return BUNDLED_PATH
    wheel = wheel_library_path()
    return wheel if wheel is not None and wheel.is_file() else BUNDLED_PATH


def library():
    """The loaded Library; raises LibraryNotFoundError (with what to do) otherwise."""
    global _library
    with _lock:
        if _library is None:
            path = library_path()
            if not os.environ.get(ENV_VAR) and unsupported_platform():
                raise LibraryNotFoundError(unsupported_platform())
            if not path.is_file():
                source = f"{ENV_VAR}={os.environ[ENV_VAR]}" if os.environ.get(ENV_VAR) else "the add-on folder"
                raise LibraryNotFoundError(f"{LIBRARY_NAME} not found ({source}: {path} does not exist). {HOW_TO_FIX}")
            _library = Library(path)
        return _library


def status():
    """(ok, message) for user interfaces: the loaded version or why it cannot load."""
    try:
        lib = library()
    except LibraryNotFoundError as e:
        return False, str(e)
    formats = lib.ft_heightfield_formats().decode()
    return True, (f"libfracterra {lib.version} (ABI {lib.abi_major}.{lib.abi_minor}) from {lib.path}; "
                  f"heightfield formats: {formats}")


def enum_values(kind_name, field):
    """{identifier: C value} of enum field `field` of params struct `kind_name`, as the
    library describes it, e.g. enum_values("hurst", "method")["AUTO"] == 5."""
    row = next(r for r in library().param_rows[kind_name] if r["name"] == field)
    return {item["name"]: item["value"] for item in row["items"]}


def reset():
    """Forgets the loaded library so the next call searches again (tests, preferences)."""
    global _library
    with _lock:
        _library = None
