# SPDX-License-Identifier: GPL-3.0-or-later
"""Tile sets on Dask for a terrain larger than memory, one task per tile:

    python3 -m fracterra.tiles --levels 16 --tile 4096 --out DIR [--scheduler tcp://H:8786] [--measure]
    python3 -m fracterra.tiles --levels 15 --tile 4096 --erode land [--strength 0.7] [--maps] \
        [--engine unreal] --out DIR                                   # an eroded terrain, seamless

The driver opens the set (fracterra.core.tiles.TileSet), runs the exact
height-range pass where one is needed as one Dask task per tile, submits one
task per tile still to do, records each finished tile's CRC-32 in the
manifest's journal as results arrive, and finishes with the VRT mosaic. A
task is pure (terrain settings, tile size, format, range, folder, column,
row -> column, row, CRC-32): each worker loads the library through the
package's binding and calls ft_tile_write, so a task lost with a killed worker
is simply run again and the set comes out byte-identical. An eroded set (or
one with maps) is the same with a recipe (fracterra.core.tiles.recipe) in
place of the settings: its range pass builds each tile once as a task and
keeps it in the set's folder, and its write task (ft_tile_write_build) takes
what was kept; --engine then cuts the finished set for a game engine with the
splat maps of its erosion.

Without --scheduler a LocalCluster of --workers processes with
--memory-limit each runs on this machine; with --scheduler tcp://HOST:8786
the same code runs on a cluster started with `dask scheduler` and
`dask worker` (docs/scale.md). The tasks live in fracterra.core.tiles, so
Dask pickles them by reference to a module every worker imports.
"""

import argparse
import json
import os
import sys
import time

from .core import params as params_mod
from .core.binding import ENV_VAR, enum_values, library
from .core.errors import FracterraError
# The tile set handle and the tasks, re-exported: one import for a script.
from .core.tiles import (FORMATS, TileSet, built, built_tile_range, extent, hurst_from_sums,  # noqa: F401
                         manifest, read_map_window, read_window, recipe, terrain_extent, cut_for_engine, tile_height_range,
                         tile_increment_sums, write_built_tile, write_tile)

class SchedulerUnreachable(FracterraError):
    """The Dask scheduler named by --scheduler did not answer in time."""


def _range_union(parts):
    """Reduces [(min, max), ...] to their union (a Dask task)."""
    return min(lo for lo, _ in parts), max(hi for _, hi in parts)


def _worker_env():
    """What each LocalCluster worker needs: this library and this package on its path."""
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = os.environ.get("PYTHONPATH", "")
    return {ENV_VAR: str(library().path),
            "PYTHONPATH": package_root + (os.pathsep + path if path else ""),
            "OMP_NUM_THREADS": "1"}


def connect(scheduler=None, workers=2, memory_limit="3GB", connect_timeout=10):
    """A dask.distributed Client: to `scheduler` (tcp://HOST:8786) or to a new LocalCluster of
    `workers` single-threaded processes with `memory_limit` each. Raises SchedulerUnreachable
    within about `connect_timeout` seconds when the scheduler does not answer."""
    from distributed import Client, LocalCluster
    if scheduler:
        try:
            return Client(scheduler, timeout=connect_timeout)
        except (OSError, TimeoutError) as e:
            raise SchedulerUnreachable(
                f"cannot reach the Dask scheduler at {scheduler} within {connect_timeout} s ({e}); start it with "
                "`dask scheduler` on that host (docs/scale.md) and check the address and port") from None
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, memory_limit=memory_limit, processes=True,
                           dashboard_address=None, env=_worker_env())
    return Client(cluster)


def _peak_rss_mib():
    """This process's peak resident memory in MiB (runs on each worker)."""
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def exact_height_range(settings, tile, client, reference=None, build=None, fmt="png16", out_dir=None):
    """The exact (min, max) of the whole terrain: one Dask task per tile, reduced on Dask in
    groups of 16 (the pass the library would otherwise run serially in the driver). With a recipe
    `build`, each task builds its tile (eroded) and keeps it in `out_dir` for the writing pass."""
    w, h = terrain_extent(settings, reference)
    cols, rows = (w - 2) // tile + 1, (h - 2) // tile + 1
    tiles = [(c, r) for r in range(rows) for c in range(cols)]
    keys = [f"fracterra-range-{c}-{r}" for c, r in tiles]
    if build is None:
        parts = client.map(tile_height_range, [c for c, _ in tiles], [r for _, r in tiles], settings=settings,
                           reference=reference, tile=tile, retries=3, key=keys)
    else:
        parts = client.map(built_tile_range, [c for c, _ in tiles], [r for _, r in tiles], recipe=build, tile=tile,
                           fmt=fmt, out_dir=out_dir, retries=3, key=keys)
    groups = [client.submit(_range_union, parts[i:i + 16], key=f"fracterra-range-group-{i}")
              for i in range(0, len(parts), 16)]
    return client.submit(_range_union, groups, key="fracterra-range-total").result()


def build_tileset(settings, out_dir, tile=4096, fmt="png16", reference=None, client=None, scheduler=None,
                  workers=2, memory_limit="3GB", connect_timeout=10, progress=True, task_threads=1, retries=3,
                  on_tile=None, erosion=None, preset="NONE", maps=False, falloff_mask=None, erosion_mask=None,
                  rain_map=None, engine=None, engine_size=0, region_size=256):
    """Writes (or resumes) the tile set of the terrain `settings` (names as in params.TERRAIN_PARAMS,
    e.g. {"method": "MIDPOINT", "levels": 14, "hurst": 0.8}) into `out_dir`, one Dask task per tile
    still to do; a new set whose height range needs the exact pass gets it from one task per tile
    too. Returns a summary dict (tiles written and skipped, seconds, peak worker memory).
    preset ("LAND", ...) and/or erosion ({setting: value} of ft_erosion_params) erode it, as
    ft_terrain_build does; maps also writes the maps; falloff_mask, erosion_mask, rain_map:
    (width, height, values) spanning the whole. engine ("unity", "unreal", "godot") then cuts the
    finished set for that engine into out_dir/ENGINE (the fracterra CLI's --engine).
    on_tile(client, done, total), if given, is called after each recorded tile (tests kill workers there)."""
    start = time.monotonic()
    settings = dict(settings)
    settings["threads"] = task_threads
    build = recipe(settings, reference, falloff_mask, erosion, preset, maps, erosion_mask, rain_map)
    if not built(build):
        build = None
    if engine is not None:
        _check_engine(engine, build)
    out = os.path.abspath(str(out_dir))
    if build is None:
        ts, pending = TileSet.open_deferred(settings, out_dir, tile, fmt, reference)
    else:
        ts, pending = TileSet.open_build(build, out_dir, tile, fmt)
    own = False
    with ts:
        try:
            cols, rows = ts.grid()
            summary = {"tiles": cols * rows, "columns": cols, "rows": rows}
            if pending:
                if client is None:
                    client, own = connect(scheduler, workers, memory_limit, connect_timeout), True
                t = time.monotonic()
                ts.set_height_range(*exact_height_range(settings, tile, client, reference, build, fmt, out))
                summary["range_seconds"] = time.monotonic() - t
            lo, hi = ts.height_range()
            todo = [(c, r) for r in range(rows) for c in range(cols) if not ts.done(c, r)]
            summary.update({"written": len(todo), "skipped": cols * rows - len(todo), "height_range": [lo, hi]})
            if todo:
                if client is None:
                    client, own = connect(scheduler, workers, memory_limit, connect_timeout), True
                from distributed import as_completed
                from tqdm import tqdm
                keys = [f"fracterra-tile-{c}-{r}" for c, r in todo]
                if build is None:
                    futures = client.map(write_tile, [c for c, _ in todo], [r for _, r in todo], settings=settings,
                                         reference=reference, tile=tile, fmt=fmt, height_min=lo, height_max=hi,
                                         out_dir=out, retries=retries, key=keys)
                else:
                    futures = client.map(write_built_tile, [c for c, _ in todo], [r for _, r in todo],
                                         recipe=build, tile=tile, fmt=fmt, height_min=lo, height_max=hi,
                                         out_dir=out, retries=retries, key=keys)
                with tqdm(total=len(todo), unit="tile", disable=not progress, file=sys.stderr) as bar:
                    for done, future in enumerate(as_completed(futures), 1):
                        col, row, crc = future.result()
                        if build is None:
                            ts.record(col, row, crc)
                        else:
                            ts.record_tile(col, row, crc)
                        bar.update(1)
                        if on_tile is not None:
                            on_tile(client, done, len(todo))
                summary["worker_peak_rss_mib"] = sorted(client.run(_peak_rss_mib).values())
        finally:
            if own:
                cluster = client.cluster
                client.close()
                if cluster is not None:
                    cluster.close()
        t = time.monotonic()
        ts.finish()
        summary["finish_seconds"] = time.monotonic() - t
    if engine is not None:
        t = time.monotonic()
        summary["engine"] = _cut_for_engine(out, engine, engine_size, region_size)
        summary["engine_seconds"] = time.monotonic() - t
    summary["seconds"] = time.monotonic() - start
    return summary


ENGINES = ("unity", "unreal", "godot")


def _check_engine(engine, build):
    if engine not in ENGINES:
        raise FracterraError(f"the engine must be one of {', '.join(ENGINES)}, got {engine!r}")
    if build is not None and build["preset"] == "NONE" and build["erosion"] is None:
        return
    if build is not None and not build["maps"]:
        # The splat maps come from the erosion maps, whose drainage area is global (each task builds the
        # whole): without them a set of any size is cut with its heights alone, in memory of a tile.
        print("fracterra-tiles: the engine tiles carry no splat maps: they come from the erosion maps (add --maps; "
              "each task then builds the whole terrain, since the drainage area is global)", file=sys.stderr)


def _cut_for_engine(folder, engine, engine_size, region_size):
    """The finished set cut for a game engine into folder/ENGINE (ft_tileset_cut_for_engine); its sidecar."""
    cut_for_engine(folder, engine, os.path.join(folder, engine), engine_size, region_size)
    with open(os.path.join(folder, engine, f"{engine}.json"), encoding="utf-8") as f:
        side = json.load(f)
    return {"folder": os.path.join(folder, engine), "tile_samples": side["tile_samples"],
            "columns": side["columns"], "rows": side["rows"]}


def _add_sums(parts):
    """Reduces [(sums, counts), ...] element-wise (a Dask task)."""
    sums = [sum(v) for v in zip(*(s for s, _ in parts))]
    counts = [sum(v) for v in zip(*(c for _, c in parts))]
    return sums, counts


def measure_tileset(settings, tile, client, method="variogram_aligned", reference=None):
    """H (aligned variogram or madogram) and D = 3 - H of the whole terrain, from one Dask task
    per tile (its increment sums) reduced on Dask; equals ft_hurst_heightfield of the whole
    wherever the whole fits. Lags up to the default band must divide `tile`."""
    w, h = terrain_extent(settings, reference)
    cols, rows = (w - 2) // tile + 1, (h - 2) // tile + 1
    tiles = [(c, r) for r in range(rows) for c in range(cols)]
    parts = client.map(tile_increment_sums, [c for c, _ in tiles], [r for _, r in tiles], settings=settings,
                       reference=reference, tile=tile, method=method, retries=3,
                       key=[f"fracterra-sums-{method}-{c}-{r}" for c, r in tiles])
    # A two-level reduction on the cluster: groups of 16, then their totals.
    groups = [client.submit(_add_sums, parts[i:i + 16], key=f"fracterra-sums-{method}-group-{i}")
              for i in range(0, len(parts), 16)]
    sums, counts = client.submit(_add_sums, groups, key=f"fracterra-sums-{method}-total").result()
    return hurst_from_sums(settings, sums, counts, method, reference)


# Erosion settings that are the terrain's, as for `fracterra tiles`: its threads, the torus of a
# terrain that tiles, its landform's sea.
_TERRAINS_OWN = {"periodic", "threads", "sea", "sea_level", "sea_fraction"}


def _add_param_flags(parser, kind, skip=()):
    """argparse flags for every setting of the library's struct `kind`, from its parameter table."""
    for p in params_mod.library_params(kind):
        if p.name in skip:
            continue
        flag = "--" + p.name.replace("_", "-")
        if p.kind == "enum":
            parser.add_argument(flag, dest=p.name, choices=[i[0].lower() for i in p.items], help=p.description)
        elif p.kind == "bool":
            parser.add_argument(flag, dest=p.name, action="store_const", const=True, help=p.description)
        else:
            parser.add_argument(flag, dest=p.name, type=int if p.kind == "int" else float, help=p.description)


def _settings_parser():
    """argparse flags for every terrain and erosion setting, from the library's parameter tables."""
    parser = argparse.ArgumentParser(
        prog="python3 -m fracterra.tiles",
        description="Write a terrain larger than memory as a tile set on Dask (one task per tile), generated "
                    "or eroded.")
    _add_param_flags(parser, "terrain")
    erosion = parser.add_argument_group("erosion", "as fracterra tiles --erode: every tile a window of the "
                                                   "eroded whole")
    presets = [p.lower() for p in enum_values("build", "erosion_preset")]
    erosion.add_argument("--erode", "--erosion-preset", dest="erosion_preset", type=str.lower, choices=presets,
                         help="erode with a preset (its settings, then the erosion flags given over them)")
    _add_param_flags(erosion, "erosion", _TERRAINS_OWN)
    erosion.add_argument("--maps", action="store_true",
                         help="also write the maps (drainage area, slope, curvature, water depth, eroded, "
                              "deposited) as float32 GeoTIFF tiles OUT/maps/MAP/ with a mosaic OUT/maps/MAP.vrt")
    for flag in ("--falloff-mask", "--erosion-mask", "--rain-map"):
        erosion.add_argument(flag, help="a raster spanning the whole terrain (as fracterra tiles takes it)")
    parser.add_argument("--tile", type=int, default=4096, help="cells per tile side (tiles hold tile + 1 samples)")
    parser.add_argument("--format", default="png16", choices=sorted(FORMATS))
    parser.add_argument("--out", required=True, help="the tile set's folder (a rerun resumes)")
    parser.add_argument("--engine", choices=ENGINES,
                        help="also cut the finished set for a game engine into OUT/ENGINE (with an eroded set's "
                             "splat maps; docs/engines.md)")
    parser.add_argument("--engine-size", type=int, default=0, help="samples per engine tile side (0: the default)")
    parser.add_argument("--region-size", type=int, default=256, help="--engine godot: Terrain3D's region size")
    parser.add_argument("--scheduler", help="tcp://HOST:8786 of a running `dask scheduler`; default: a LocalCluster")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    parser.add_argument("--memory-limit", default="3GB", help="LocalCluster memory limit per worker")
    parser.add_argument("--connect-timeout", type=float, default=10, help="seconds to wait for --scheduler")
    parser.add_argument("--task-threads", type=int, default=1, help="library threads per task")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--measure", action="store_true",
                        help="also H (aligned variogram) and D of the whole from per-tile sums reduced on Dask")
    return parser


def _mask(path):
    """(width, height, values) of a mask raster, or None."""
    if not path:
        return None
    from .core.raster import read_heightfield
    with read_heightfield(path) as hf:
        return hf.width, hf.height, hf.to_array()


def main(argv=None):
    args = _settings_parser().parse_args(argv)
    values = vars(args)
    names = {p.name for p in params_mod.library_params("terrain")}
    settings = {k: (v.upper() if isinstance(v, str) else v) for k, v in values.items()
                if k in names and v is not None}
    erosion_names = {p.name for p in params_mod.library_params("erosion")} - _TERRAINS_OWN
    erosion = {k: (v.upper() if isinstance(v, str) else v) for k, v in values.items()
               if k in erosion_names and v is not None} or None
    try:
        falloff_mask = _mask(args.falloff_mask)
        if falloff_mask is not None:
            settings["falloff"] = "CUSTOM"
        erosion_mask, rain_map = _mask(args.erosion_mask), _mask(args.rain_map)
        if erosion is None and (erosion_mask or rain_map):
            erosion = {}
        client = connect(args.scheduler, args.workers, args.memory_limit, args.connect_timeout)
        try:
            summary = build_tileset(settings, args.out, args.tile, args.format, client=client,
                                    progress=not args.quiet, task_threads=args.task_threads, erosion=erosion,
                                    preset=args.erosion_preset or "NONE", maps=args.maps,
                                    falloff_mask=falloff_mask, erosion_mask=erosion_mask, rain_map=rain_map,
                                    engine=args.engine, engine_size=args.engine_size, region_size=args.region_size)
            if args.measure:
                summary["measure"] = measure_tileset(dict(settings, threads=args.task_threads), args.tile, client)
        finally:
            cluster = client.cluster
            client.close()
            if cluster is not None:
                cluster.close()
    except FracterraError as e:
        print(f"fracterra-tiles: error: {e}", file=sys.stderr)
        return 2
    print(json.dumps(summary))
    return 0


def _identifiers(table, values):
    """Keyword values as the core's settings hold them: an enum by its identifier ("MIDPOINT")."""
    from .core import rows
    out = {}
    for name, value in values.items():
        row = table.rows[name]
        out[name] = rows.enum_item(row, rows.enum_value(row, value))["name"] if row["type"] == "enum" else value
    return out


def write_tiles(out_dir, *, tile=4096, format="png16", size=None, erode=None, maps=False, erosion_mask=None,
                rain_map=None, falloff_mask=None, reference=None, threads=0, progress=None, **settings):
    """Writes (or resumes) the tile set of a terrain on this machine, one tile after another, as
    `fracterra tiles` does: the same folder, manifest, tiles and mosaic (byte for byte) as the
    CLI and the Dask driver give. Keywords as ft.terrain()'s (erode=, strength=, maps=, the
    masks as arrays spanning the whole); tile: cells per tile side (tiles hold tile + 1
    samples); format: png16 or tiff. progress: None or callable(done, total). Returns a summary
    dict (tiles, written, skipped, height_range, seconds)."""
    from .arrays import mask_of
    from .keywords import Table, split
    from .pipeline import _size
    start = time.monotonic()
    tables = {"terrain": Table("terrain", skip=("threads",)), "erosion": Table("erosion", skip=tuple(_TERRAINS_OWN))}
    given = split(settings, tables)
    if size is not None:
        for k, v in _size(size).items():
            given["terrain"].setdefault(k, v)
    terrain = _identifiers(tables["terrain"], given["terrain"])
    terrain["threads"] = threads
    erosion = _identifiers(tables["erosion"], given["erosion"]) or None

    def as_map(m, what):
        return None if m is None else mask_of(m, what)

    fm, em, rm = as_map(falloff_mask, "the falloff mask"), as_map(erosion_mask, "the erosion mask"), \
        as_map(rain_map, "the rain map")
    if fm is not None:
        terrain["falloff"] = "CUSTOM"
    if erosion is None and (em is not None or rm is not None):
        erosion = {}
    ref = None
    if reference is not None:
        from .pipeline import _reference
        ref = _reference(reference)
    from .pipeline import _preset
    from .core import rows
    preset_row = next(r for r in library().param_rows["build"] if r["name"] == "erosion_preset")
    preset = rows.enum_item(preset_row, _preset(erode))["name"]
    build = recipe(terrain, ref, fm, erosion, preset, maps, em, rm)
    if not built(build):
        build = None
    out = os.path.abspath(os.fspath(out_dir))
    if build is None:
        ts, pending = TileSet.open_deferred(terrain, out, tile, format, ref)
    else:
        ts, pending = TileSet.open_build(build, out, tile, format)
    with ts:
        cols, rows_ = ts.grid()
        every = [(c, r) for r in range(rows_) for c in range(cols)]
        if pending:
            parts = [tile_height_range(c, r, terrain, ref, tile) if build is None
                     else built_tile_range(c, r, build, tile, format, out) for c, r in every]
            ts.set_height_range(*_range_union(parts))
        lo, hi = ts.height_range()
        todo = [(c, r) for c, r in every if not ts.done(c, r)]
        for done, (c, r) in enumerate(todo, 1):
            if build is None:
                ts.record(*write_tile(c, r, terrain, ref, tile, format, lo, hi, out))
            else:
                ts.record_tile(*write_built_tile(c, r, build, tile, format, lo, hi, out))
            if progress is not None:
                progress(done, len(todo))
        ts.finish()
    return {"tiles": cols * rows_, "columns": cols, "rows": rows_, "written": len(todo),
            "skipped": cols * rows_ - len(todo), "height_range": [lo, hi], "seconds": time.monotonic() - start}


class _CallableModule(type(sys)):
    """fracterra.tiles is this module (the Dask driver, `python3 -m fracterra.tiles`) and, called,
    the one-machine writer: ft.tiles(out_dir, ...) is write_tiles(out_dir, ...)."""

    def __call__(self, out_dir, **kw):
        return write_tiles(out_dir, **kw)


sys.modules[__name__].__class__ = _CallableModule


if __name__ == "__main__":
    # Run from the package module, not from __main__: Dask pickles the driver's
    # own reductions by reference to fracterra.tiles, which every worker imports
    # (functions of __main__ would be pickled by value, with their ctypes globals).
    from fracterra import tiles as _tiles
    sys.exit(_tiles.main())
