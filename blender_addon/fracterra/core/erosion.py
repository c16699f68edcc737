# SPDX-License-Identifier: GPL-3.0-or-later
"""Erosion through the C ABI (fracterra/erosion.h): ft_erode and its maps,
bpy-free (the pytest suite uses it directly).

The settings are the library's ft_erosion_params rows (core.params.EROSION_PARAMS),
stored with a terrain's own settings; a preset (ft_erosion_preset) fills them.
"""

import ctypes
from ctypes import byref, c_void_p

from . import params as params_mod
from .binding import library
from .terrain import Heightfield, _ProgressBridge, attach_map

# ft_erosion_map order (FT_MAP_DRAINAGE_AREA .. FT_MAP_DEPOSITED).
MAPS = ("drainage_area", "slope", "curvature", "water_depth", "eroded", "deposited")
# The library's presets (presets.cpp), by id; the old ids "valleys", "land",
# "rain" and "scree" are aliases the library still takes.
PRESETS = ("gentle_valleys", "rugged_mountains", "badlands", "alluvial_fans", "scree_slopes")
COUNTS = ("fluvial_steps", "hydraulic_iterations", "thermal_iterations")
# What a preset sets (ABI 2.14; scree_years 2.28): the run (its duration; None: 0), the landscape
# model's rates, and the expert pass counts (0 in every preset).
PRESET_FIELDS = ("duration", "erodibility", "area_exponent", "diffusion", "deposition", "talus_degrees",
                 "scree_years") + COUNTS


def _fill(p, values):
    for param in params_mod.EROSION_PARAMS:
        if param.name in values:
            setattr(p, param.name, param.c_value(values[param.name]))
    return p


def erosion_struct(values=None, preset=None, terrain=None, **overrides):
    """An ft_erosion_params from the library's init (or `preset`, fitted to the
    Heightfield `terrain` when given: see fitted_uplift), then the values by name."""
    lib = library()
    p = lib.erosion_params_type()
    if preset and terrain is not None:
        lib.check(lib.ft_erosion_preset_fitted(preset.lower().encode(), terrain.handle, byref(p)))
    elif preset:
        lib.check(lib.ft_erosion_preset(preset.lower().encode(), byref(p)))
    else:
        lib.check(lib.ft_erosion_params_init(byref(p)))
    merged = dict(values or {})
    merged.update(overrides)
    return _fill(p, merged)


def preset_values(preset):
    """{setting: value} of a preset (an id of PRESETS, its label, or an old id), as the library defines it."""
    p = erosion_struct(preset=preset)
    return {param.name: _from_c(param, getattr(p, param.name)) for param in params_mod.EROSION_PARAMS}


FITTED = ("uplift", "uplift_follows_terrain")


def fitted_uplift(preset, terrain):
    """{"uplift": ..., "uplift_follows_terrain": ...} of `preset` for Heightfield
    `terrain` (ft_erosion_preset_fitted). Since ABI 2.14 the presets are in world
    units and years and fit nothing: uplift 0, kept for callers of the old API."""
    p = erosion_struct(preset=preset, terrain=terrain)
    return {param.name: _from_c(param, getattr(p, param.name))
            for param in params_mod.EROSION_PARAMS if param.name in FITTED}


def _from_c(param, value):
    if param.kind == "bool":
        return bool(value)
    if param.kind == "int":
        return int(value)
    return float(value)


def requested(values):
    """True when the settings ask for any erosion: a run (strength x duration > 0)
    or an expert pass."""
    run = float(values.get("strength", 0.5)) * float(values.get("duration", 0.0))
    return run > 0 or any(int(values.get(name, 0)) > 0 for name in COUNTS)


def erode(hf, values=None, preset=None, periodic=False, threads=0, progress=None, maps=True,
          erosion_mask=None, rain_map=None):
    """Erodes Heightfield `hf`: (eroded Heightfield, {map name: Heightfield}) (close them,
    or use erode_arrays). erosion_mask, rain_map: None or (width, height, values in
    [0, 1]) spanning the terrain (see terrain.attach_map). progress: None or
    callable(fraction) -> True to cancel (raises CancelledError)."""
    p = erosion_struct(values, preset, terrain=hf)  # as `fracterra erode --preset`
    _keep = (attach_map(p, "erosion_mask", erosion_mask, "the erosion mask"),
             attach_map(p, "rain_map", rain_map, "the rain map"))
    p.periodic = 1 if periodic else 0
    p.threads = threads
    return erode_struct(hf, p, progress, maps)


def erode_struct(hf, p, progress=None, maps=True):
    """ft_erode of Heightfield `hf` with a filled ft_erosion_params `p` (the Python
    package fills it from keyword arguments): as erode()."""
    lib = library()
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    out = c_void_p()
    handles = (c_void_p * len(MAPS))()
    status = lib.ft_erode(hf.handle, byref(p), byref(out),
                          ctypes.cast(handles, ctypes.POINTER(c_void_p)) if maps else None)
    bridge.reraise()
    lib.check(status)
    made = {name: Heightfield(c_void_p(h)) for name, h in zip(MAPS, handles) if h} if maps else {}
    return Heightfield(out), made


def erode_arrays(hf, **kw):
    """As erode(), but the maps come back as array.array('f') (row-major) and are closed."""
    eroded, made = erode(hf, **kw)
    arrays = {}
    for name, m in made.items():
        with m:
            arrays[name] = m.to_array()
    return eroded, arrays


__all__ = ["MAPS", "PRESETS", "PRESET_FIELDS", "FITTED", "erosion_struct", "erode_struct", "fitted_uplift", "preset_values", "requested", "erode", "erode_arrays"]
