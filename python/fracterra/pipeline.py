# SPDX-License-Identifier: GPL-3.0-or-later
"""The pipeline from numpy: terrain() is ft_terrain_build (generate ->
landform -> erode -> maps -> rivers, as `fracterra terrain` and the Blender
add-on run it), erode() and rivers() are the pipeline's erode and rivers
stages on a terrain already made (ft_terrain_erode, ft_terrain_rivers), so
erode(terrain(p)) is terrain(p, erode=...) bit for bit: a Terrain carries the
world its later stages need (world size, whether it tiles, its sea)."""

from __future__ import annotations

import ctypes
import math
import numbers
from collections import namedtuple
from ctypes import byref, c_int64, c_void_p
from typing import Any, Optional

from .arrays import Terrain, from_library, grid, mask_of, to_library, world_of, world_size_or_default
from .core.binding import TerrainWorld, library
from .core.erosion import MAPS
from .core.errors import InvalidArgumentError
from .core.rivers import RiverNetwork
from .core.terrain import Heightfield, _ProgressBridge, attach_falloff_mask, attach_map, attach_reference
from .keywords import Table, document, split
from .rivers import Rivers


# terrain(..., maps=True or rivers=...) returns these three; a field not asked for is None.
Build = namedtuple("Build", "terrain maps rivers")

# Erosion settings that are the terrain's in terrain() (as the CLI's kTerrainsOwn): its threads
# serve every stage, a terrain that tiles erodes as a torus, its landform's sea is erosion's.
_TERRAINS_OWN = ("periodic", "threads", "sea", "sea_level", "sea_fraction")
_OWN = ("size", "center", "erode", "maps", "rivers", "erosion_mask", "rain_map", "falloff_mask", "reference",
        "threads", "progress")


def _tables():
    return {"terrain": Table("terrain", skip=("threads",)), "build": Table("build", skip=("threads", "erosion_preset")),
            "erosion": Table("erosion", skip=_TERRAINS_OWN)}


def _size(value) -> dict:
    """size=N, (w, h) or "WxH", as the CLI's --size: width and height."""
    if isinstance(value, str):
        parts = value.lower().split("x")
        if len(parts) not in (1, 2) or not all(p.strip().isdigit() for p in parts):
            raise InvalidArgumentError(f"size must be N, (width, height) or 'WxH' (e.g. 1024 or '2048x1024'), "
                                       f"got {value!r}")
        value = tuple(int(p) for p in parts)
    def integer(v):
        return isinstance(v, numbers.Integral) and not isinstance(v, bool)
    if integer(value):
        return {"width": int(value), "height": int(value)}
    if isinstance(value, (tuple, list)) and len(value) in (1, 2) and all(integer(v) for v in value):
        return {"width": int(value[0]), "height": int(value[-1])}
    raise TypeError(f"size must be N, (width, height) or 'WxH' (integers), got {value!r}")


def _preset(value) -> int:
    """The ft_build_params.erosion_preset value of a preset id, old id or label (as the CLI's --erode)."""
    from .core import rows
    row = library().param_rows["build"]
    row = next(r for r in row if r["name"] == "erosion_preset")
    if value is None or value is False:
        return rows.enum_value(row, "none")
    try:
        return rows.enum_value(row, value)
    except ValueError:
        # The preset ids ("rugged_mountains") are the labels' spelling; the library's own names are the old ids.
        raise InvalidArgumentError(f"unknown erosion preset {value!r}: one of {rows.allowed_text(row)}") from None


def _preset_name(value) -> str:
    """ft_erosion_preset's name of a preset value ("land")."""
    from .core import rows
    row = next(r for r in library().param_rows["build"] if r["name"] == "erosion_preset")
    return rows.enum_item(row, value)["name"].lower()


def _check_mask_shape(mask, shape, what):
    """A mask spans the terrain corner to corner (the library resamples it): it must have the
    terrain's shape or its proportions (within a sample), so that a mask of another terrain is
    not stretched over this one silently."""
    mh, mw = mask.shape
    th, tw = shape
    if (mh, mw) != (th, tw) and abs(mh * tw / th - mw) > 1:
        raise InvalidArgumentError(f"{what} is {mw} x {mh} samples (width x height); it spans the terrain, "
                                   f"{tw} x {th}: give one of that shape or of its proportions")


def _build_struct(p_terrain, erosion, preset, threads, bridge, rivers_struct=None):
    lib = library()
    b = lib.build_params_type()
    lib.check(lib.ft_build_params_init(byref(b)))
    b.terrain = ctypes.pointer(p_terrain) if p_terrain is not None else None
    if erosion is not None:
        b.erosion = ctypes.pointer(erosion)
    b.erosion_preset = preset
    b.threads = threads
    if rivers_struct is not None:
        b.rivers = ctypes.pointer(rivers_struct)
    b.progress = bridge.c_fn
    return b


def _hydrology(settings: Optional[dict]):
    lib = library()
    h = lib.hydrology_params_type()
    lib.check(lib.ft_hydrology_params_init(byref(h)))
    Table("hydrology", skip=("threads",)).fill(h, {k: v for k, v in (settings or {}).items() if v is not None})
    return h


def _maps(handles, period_overlap, sea_level) -> dict:
    out = {}
    for name, h in zip(MAPS, handles):
        with Heightfield(c_void_p(h)) as m:
            out[name] = from_library(m, period_overlap, sea_level)
    return out


def window(x0: int, y0: int, width: int, height: int, *, maps: bool = False, **kw):
    """The samples [x0, x0 + width) x [y0, y0 + height) of what terrain(**kw)
    makes (ft_terrain_build_window), eroded or not, heights and maps: the
    same bits as those samples of the whole, in the memory of the window (and
    the erosion's reach). Its world size is the window's share of the whole's.
    Takes terrain()'s keywords but rivers; refused for spectral synthesis and
    a sea given as a fraction (their whole defines them). Returns a Terrain,
    or with maps=True a Build(terrain, maps, None)."""
    if kw.get("rivers"):
        raise InvalidArgumentError("a window has no rivers of its own: trace them on the whole (ft.rivers)")
    return terrain(maps=maps, _window=(int(x0), int(y0), int(width), int(height)), **kw)


def terrain(*, size=None, center=None, erode=None, maps: bool = False, rivers=False, erosion_mask=None,
            rain_map=None, falloff_mask=None, reference=None, threads: int = 0, progress=None, _window=None,
            **settings):
    """A fractal terrain through the library's pipeline (ft_terrain_build),
    as `fracterra terrain` and the Blender add-on make it: the same settings
    give the same bits. Returns a Terrain (numpy float32 with its world); with
    maps=True or rivers, a Build(terrain, maps, rivers).

    size: N, (width, height) or "WxH", as the CLI's --size (width and height).
    center: (x, y), the Mandelbrot view's centre (center_x, center_y).
    erode: an erosion preset, by id ("rugged_mountains"), old id ("land") or
    label ("Rugged Mountains"): fitted to the generated terrain, it sets the
    pass counts and what it changes from the defaults; erosion settings given
    (strength=, duration=, ...) set the rest. Erosion settings without a preset
    erode with those settings.
    maps: also the six maps (drainage_area, slope, curvature, water_depth,
    eroded, deposited) of the result, as Terrains.
    rivers: True (the defaults) or a dict of ft_hydrology_params settings: the
    rivers, lakes and sea of the result (a Rivers), traced as the pipeline's
    last stage (a terrain that tiles gives rivers that wrap; its own sea is
    theirs); the terrain returned is then carved along them (Rivers.carve).
    erosion_mask, rain_map: 2-D arrays in [0, 1] spanning the terrain: where
    erosion acts, where rain falls. falloff_mask: the custom falloff's mask.
    reference: a (2^m + 1)^2 array of heights the terrain passes through
    (midpoint, additions).
    threads: worker threads, 0 for all cores (the result never depends on it).
    progress: None or callable(fraction) returning True to cancel (raises CancelledError).
    """
    lib = library()
    tables = _tables()
    given = split(settings, tables, _OWN)
    if size is not None:
        for k, v in _size(size).items():
            given["terrain"].setdefault(k, v)
    if center is not None:
        if not (isinstance(center, (tuple, list)) and len(center) == 2):
            raise TypeError(f"center must be (x, y), got {center!r}")
        given["terrain"]["center_x"], given["terrain"]["center_y"] = (float(c) for c in center)
    t = lib.terrain_params_type()
    lib.check(lib.ft_terrain_params_init(byref(t)))
    tables["terrain"].fill(t, given["terrain"])
    t.threads = threads
    if falloff_mask is not None:
        # As the CLI's --falloff-mask: it sets the custom falloff, and goes with no other.
        falloff = given["terrain"].get("falloff", "custom")
        if str(falloff).lower() not in ("custom", "none"):
            raise InvalidArgumentError(f"falloff_mask is the custom falloff's mask; it cannot go with "
                                       f"falloff={falloff!r}")
        tables["terrain"].fill(t, {"falloff": "custom"})
    keep = [attach_reference(t, _reference(reference)), attach_falloff_mask(t, _falloff(falloff_mask))]
    # The grid's shape, for the masks' check (a sea of the whole's quantile has no windows, so
    # the extent is asked of the same terrain without it).
    shaped = type(t).from_buffer_copy(t)
    shaped.sea = 0
    w, h = c_int64(), c_int64()
    lib.check(lib.ft_terrain_extent(byref(shaped), 0, byref(w), byref(h)))
    shape = (h.value, w.value)
    e = None
    if given["erosion"] or erosion_mask is not None or rain_map is not None:
        e = lib.erosion_params_type()
        lib.check(lib.ft_erosion_params_init(byref(e)))
        tables["erosion"].fill(e, given["erosion"])
        keep += _attach_maps(e, erosion_mask, rain_map, shape)
    hydrology = None
    if rivers:
        if not (rivers is True or isinstance(rivers, dict)):
            raise TypeError(f"rivers is True, False or a dict of ft_hydrology_params settings, got {rivers!r}")
        hydrology = _hydrology(rivers if isinstance(rivers, dict) else None)
    bridge = _ProgressBridge(progress)
    b = _build_struct(t, e, _preset(erode), threads, bridge, hydrology)
    tables["build"].fill(b, given["build"])
    out, net = c_void_p(), c_void_p()
    handles = (c_void_p * len(MAPS))()
    world = TerrainWorld()
    lib.check(lib.ft_terrain_world_init(byref(world)))
    map_out = ctypes.cast(handles, ctypes.POINTER(c_void_p)) if maps else None
    if _window is not None:
        status = lib.ft_terrain_build_window(byref(b), *_window, byref(out), map_out)
        # A window does not tile; its sea (a height: a fraction has no windows) is the terrain's.
        world.sea_level = t.sea_level if rows_of_sea(t) == "height" else math.nan
    else:
        status = lib.ft_terrain_build_world(byref(b), byref(out), map_out, byref(net) if rivers else None,
                                            byref(world))
    bridge.reraise()
    lib.check(status)
    del keep
    with Heightfield(out) as hf:
        z = from_library(hf, world.period_overlap, world.sea_level)
    made = _maps(handles, world.period_overlap, world.sea_level) if maps else None
    water = None
    if rivers:
        with RiverNetwork(net) as network:
            water = Rivers(network, z, carved=True)
    return Build(z, made, water) if maps or rivers else z


def rows_of_sea(t) -> str:
    """The name of ft_terrain_params.sea's value in `t` ("none", "height", "fraction")."""
    from .core import rows
    row = next(r for r in library().param_rows["terrain"] if r["name"] == "sea")
    return rows.enum_item(row, t.sea)["cli"]


def _reference(reference):
    if reference is None:
        return None
    a = grid(reference, "the reference grid")
    if a.shape[0] != a.shape[1]:
        raise InvalidArgumentError(f"the reference grid is {a.shape[1]} x {a.shape[0]}; it must be square, "
                                   f"2^m + 1 per side")
    return a.shape[0], a.ravel()


def _falloff(mask):
    return None if mask is None else mask_of(mask, "the falloff mask")


def _attach_maps(e, erosion_mask, rain_map, shape) -> list:
    keep = []
    for field, m, what in (("erosion_mask", erosion_mask, "the erosion mask"), ("rain_map", rain_map, "the rain map")):
        if m is None:
            continue
        width, height, a = mask_of(m, what)
        _check_mask_shape(a, shape, what)
        keep.append(attach_map(e, field, (width, height, a), what))
    return keep


def _world(z, periodic, sea_given) -> TerrainWorld:
    """z's world for the library; periodic (True/False) and sea settings given replace its own."""
    lib = library()
    w = TerrainWorld()
    lib.check(lib.ft_terrain_world_init(byref(w)))
    _ws, overlap, sea_level = world_of(z)
    if periodic is not None:
        overlap = (overlap if overlap >= 0 else 0) if periodic else -1
    w.period_overlap = overlap
    w.sea_level = math.nan if sea_given else sea_level
    return w


def erode(z, preset: Optional[str] = None, *, maps: bool = True, erosion_mask=None, rain_map=None,
          threads: int = 0, progress=None, **settings) -> tuple:
    """Erodes `z` as the pipeline's erode stage (ft_terrain_erode): returns
    (eroded Terrain, {map name: Terrain}) with the maps drainage_area, slope,
    curvature, water_depth, eroded and deposited ({} with maps=False).

    z: a Terrain (its world size, whether it tiles and its sea are read: a
    terrain of ft.terrain(p) erodes here as ft.terrain(p, erode=...) erodes it,
    bit for bit) or a 2-D array (a world of 10 units, said on stderr).
    preset: an erosion preset by id, old id or label, as terrain(erode=...):
    fitted to z, it sets the pass counts and what it changes from the
    defaults; the settings given override its values, as `fracterra erode
    --preset` takes flags (terrain(erode=...) keeps a preset's values, as
    `fracterra terrain --erode`: the same only for settings no preset sets,
    such as strength). periodic=True/False and sea settings replace z's own.
    """
    lib = library()
    table = Table("erosion", skip=("threads",))
    given = split(settings, {"erosion": table}, ("maps", "erosion_mask", "rain_map", "threads", "progress"))["erosion"]
    periodic = given.pop("periodic", None)
    sea_given = any(k in given for k in ("sea", "sea_level", "sea_fraction"))
    world = _world(z, periodic, sea_given)
    with to_library(z, world_size=world_size_or_default(z)) as hf:
        e = None
        preset_value = _preset(preset)
        if given or erosion_mask is not None or rain_map is not None:
            e = lib.erosion_params_type()
            if given and preset_value != _preset(None):
                # As `fracterra erode --preset X --flag V`: the preset fitted to z, then the settings
                # given over it (the pipeline alone keeps a preset's values over the given ones).
                lib.check(lib.ft_erosion_preset_fitted(_preset_name(preset_value).encode(), hf.handle, byref(e)))
                preset_value = _preset(None)
            else:
                lib.check(lib.ft_erosion_params_init(byref(e)))
            table.fill(e, given)
            keep = _attach_maps(e, erosion_mask, rain_map, (hf.height, hf.width))  # noqa: F841 (kept alive)
        bridge = _ProgressBridge(progress)
        b = _build_struct(None, e, preset_value, threads, bridge)
        out = c_void_p()
        handles = (c_void_p * len(MAPS))()
        status = lib.ft_terrain_erode(byref(b), hf.handle, byref(world), byref(out),
                                      ctypes.cast(handles, ctypes.POINTER(c_void_p)) if maps else None)
        bridge.reraise()
        lib.check(status)
        with Heightfield(out) as eroded:
            result = from_library(eroded, world.period_overlap, world.sea_level)
        return result, (_maps(handles, world.period_overlap, world.sea_level) if maps else {})


def rivers(z, *, threads: int = 0, progress=None, **settings) -> Rivers:
    """The rivers, lakes and sea of `z` as the pipeline's rivers stage
    (ft_terrain_rivers): a terrain that tiles is routed as its torus (rivers
    wrap), its own sea (a Terrain's sea_level) is theirs; periodic= and sea
    settings given replace z's own. Returns a Rivers (arrays, and writers to
    GeoJSON and GeoPackage)."""
    lib = library()
    table = Table("hydrology", skip=("threads",))
    given = split(settings, {"hydrology": table}, ("threads", "progress"))["hydrology"]
    periodic = given.pop("periodic", None)
    world = _world(z, periodic, any(k in given for k in ("sea", "sea_level", "sea_fraction")))
    h = _hydrology(given)
    with to_library(z, world_size=world_size_or_default(z)) as hf:
        bridge = _ProgressBridge(progress)
        b = _build_struct(None, None, _preset(None), threads, bridge, h)
        net = c_void_p()
        status = lib.ft_terrain_rivers(byref(b), hf.handle, byref(world), byref(net))
        bridge.reraise()
        lib.check(status)
        with RiverNetwork(net) as network:
            return Rivers(network, Terrain(z, hf.world_size, world.period_overlap, world.sea_level))


def _annotate() -> None:
    from inspect import Parameter
    ko, pos = Parameter.KEYWORD_ONLY, Parameter.POSITIONAL_OR_KEYWORD
    threads = Parameter("threads", ko, default=0, annotation=int)
    progress = Parameter("progress", ko, default=None)
    own = [Parameter(n, ko, default=d) for n, d in (("size", None), ("center", None), ("erode", None), ("maps", False),
                                                     ("rivers", False), ("erosion_mask", None), ("rain_map", None),
                                                     ("falloff_mask", None), ("reference", None))]
    t = _tables()
    from .core import rows
    from .core.erosion import PRESETS
    preset_row = next(r for r in library().param_rows["build"] if r["name"] == "erosion_preset")
    presets = (f"Erosion presets (erode=, erode()'s preset): {rows.allowed_text(preset_row)}; the ids "
               f"{', '.join(PRESETS)} and the labels work too, as on the command line.")
    document(terrain, own + [threads, progress],
             [("Terrain settings", t["terrain"]), ("Pipeline settings", t["build"]),
              ("Erosion settings (with erode=, or alone)", t["erosion"])], presets)
    document(erode, [Parameter("z", pos, annotation=Any), Parameter("preset", pos, default=None),
                     Parameter("maps", ko, default=True, annotation=bool), Parameter("erosion_mask", ko, default=None),
                     Parameter("rain_map", ko, default=None), threads, progress],
             [("Erosion settings", Table("erosion", skip=("threads",)))], presets)
    document(window, [Parameter(n, pos, annotation=int) for n in ("x0", "y0", "width", "height")] +
             [Parameter("maps", ko, default=False)] + [q for q in own if q.name not in ("maps", "rivers")] +
             [threads, progress],
             [("Terrain settings", t["terrain"]), ("Pipeline settings", t["build"]),
              ("Erosion settings (with erode=, or alone)", t["erosion"])])
    document(rivers, [Parameter("z", pos, annotation=Any), threads, progress],
             [("Rivers settings", Table("hydrology", skip=("threads",)))])


__all__ = ["terrain", "window", "erode", "rivers", "Build"]
