# SPDX-License-Identifier: GPL-3.0-or-later
"""The whole terrain in one library call (fracterra/pipeline.h,
ft_terrain_build): generate -> landform -> erode -> maps, with one progress
callback. bpy-free; the add-on's Erode step and the pytest suite call it, and
`fracterra terrain --erode` calls the same function in the library, so the
same settings give the same bits everywhere.
"""

import ctypes
from ctypes import byref, c_void_p

from .binding import enum_values, library
from .erosion import MAPS, erosion_struct
from .errors import InvalidArgumentError
from .params import fill_struct
from .rivers import RiverNetwork, WaterArrays
from .terrain import Heightfield, _ProgressBridge, attach_falloff_mask, attach_map, attach_reference, terrain_struct


def build_terrain(values, reference=None, falloff_mask=None, erosion=None, preset="NONE", maps=False, threads=0,
                  progress=None, erosion_mask=None, rain_map=None, window=None):
    """See _build; returns (Heightfield, maps or None). window: None (the
    whole) or (x0, y0, width, height), samples of the whole terrain
    (ft_terrain_build_window, ABI 2.26): the same bits as those samples of
    the whole, heights and maps; the erosion mask and rain map still span
    the whole terrain."""
    hf, arrays, _water = _build(values, reference, falloff_mask, erosion, preset, maps, threads, progress,
                                erosion_mask, rain_map, None, window)
    return hf, arrays


def build_terrain_rivers(values, rivers, reference=None, falloff_mask=None, erosion=None, preset="NONE", maps=False,
                         threads=0, progress=None, erosion_mask=None, rain_map=None):
    """build_terrain with the pipeline's rivers stage (ABI 2.20): `rivers` is a
    list of Params (core.params.RIVERS_PARAMS: each has the ft_hydrology_params
    field it fills; None: no rivers) and `values` their values by name. The
    library routes a terrain that tiles as a torus (rivers wrap) and gives the
    rivers the terrain's own sea. Returns (Heightfield, maps or None,
    core.rivers.WaterArrays or None)."""
    return _build(values, reference, falloff_mask, erosion, preset, maps, threads, progress, erosion_mask, rain_map,
                  rivers)


def _build(values, reference, falloff_mask, erosion, preset, maps, threads, progress, erosion_mask, rain_map, rivers,
           window=None):
    """Builds the terrain of `values` (settings by name, as generate_terrain
    takes them, with its reference and falloff mask); returns (Heightfield,
    {map name: array.array('f')} or None). Close the Heightfield (or use `with`).

    erosion: None (no erosion unless a preset) or {setting: value} of
    ft_erosion_params (core.params.EROSION_PARAMS); the library decides
    whether the terrain erodes as a torus (when it tiles). preset: "NONE"
    or a preset id of ft_build_params.erosion_preset ("VALLEYS", ..., "BADLANDS"): fitted to the generated terrain, it
    sets the pass counts and what it changes from the defaults; the rest comes
    from `erosion`. erosion_mask, rain_map: None or (width, height, values in
    [0, 1]) spanning the terrain (terrain.attach_map): where erosion acts and
    where rain falls. maps: also return the six maps (ft_erosion_map order, names
    in core.erosion.MAPS). progress: None or callable(fraction) -> True to
    cancel (raises CancelledError)."""
    lib = library()
    t = terrain_struct(values)
    _ref_buf = attach_reference(t, reference)
    _mask_buf = attach_falloff_mask(t, falloff_mask)
    e = erosion_struct(erosion) if erosion is not None or erosion_mask or rain_map else None
    _maps_bufs = (attach_map(e, "erosion_mask", erosion_mask, "the erosion mask"),
                  attach_map(e, "rain_map", rain_map, "the rain map"))
    p = lib.build_params_type()
    lib.check(lib.ft_build_params_init(byref(p)))
    p.terrain = ctypes.pointer(t)
    if e is not None:
        p.erosion = ctypes.pointer(e)
    presets = enum_values("build", "erosion_preset")
    if preset not in presets:
        raise InvalidArgumentError(f"the erosion preset must be one of {', '.join(presets)}, got {preset!r}")
    p.erosion_preset = presets[preset]
    p.threads = threads
    if rivers is not None:
        h = lib.hydrology_params_type()
        lib.check(lib.ft_hydrology_params_init(byref(h)))
        fill_struct(h, values, rivers)
        p.rivers = ctypes.pointer(h)
    bridge = _ProgressBridge(progress)
    p.progress = bridge.c_fn
    out, net = c_void_p(), c_void_p()
    handles = (c_void_p * len(MAPS))()
    map_out = ctypes.cast(handles, ctypes.POINTER(c_void_p)) if maps else None
    if window is not None:
        x0, y0, width, height = window
        status = lib.ft_terrain_build_window(byref(p), x0, y0, width, height, byref(out), map_out)
    elif rivers is None:
        status = lib.ft_terrain_build(byref(p), byref(out), map_out)
    else:
        status = lib.ft_terrain_build_rivers(byref(p), byref(out), map_out, byref(net))
    bridge.reraise()
    lib.check(status)
    hf = Heightfield(out)
    water = None
    if rivers is not None:
        with RiverNetwork(net) as network:
            water = WaterArrays(network, hf.width, hf.height, hf.world_size / (hf.width - 1))
    if not maps:
        return hf, None, water
    arrays = {}
    for name, h in zip(MAPS, handles):
        with Heightfield(c_void_p(h)) as m:
            arrays[name] = m.to_array()
    return hf, arrays, water


__all__ = ["build_terrain", "build_terrain_rivers"]
