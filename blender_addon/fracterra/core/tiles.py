"""Tile sets on Dask: a terrain larger than memory written as tiles, one task per tile.

The library does the tile logic (fracterra/tiles.h): the driver opens the set
(which refuses a folder holding another terrain and, for plain midpoint,
bounds the common height range from a coarse pass), runs the exact range pass
where one is needed as one Dask task per tile, submits one Dask task per tile
still to do, records each finished tile's CRC-32 in the manifest's journal as
results arrive, and finishes with the VRT mosaic. A task is pure (terrain settings, tile size, format, range,
folder, column, row -> column, row, CRC-32): each worker loads
libfracterra.so through this binding and calls ft_tile_write, which writes
under a temporary name and renames, so a task lost with a killed worker is
simply run again and the set comes out byte-identical.

Without --scheduler a LocalCluster of --workers processes with
--memory-limit each runs on this machine; with --scheduler tcp://HOST:8786
the same code runs on a cluster started with `dask scheduler` and
`dask worker` (docs/scale.md). bpy-free:

    PYTHONPATH=blender_addon FRACTERRA_LIBRARY=build/native/libfracterra.so \\
        /usr/bin/python3 -m fracterra.core.tiles --levels 16 --tile 4096 --out DIR
"""

import argparse
import ctypes
import json
import os
import sys
import time
from ctypes import byref, c_double, c_int32, c_int64, c_size_t, c_uint32, c_void_p

from . import params as params_mod
from .binding import ENV_VAR, HurstResult, library
from .errors import FracterraError, InvalidArgumentError
from .handle import LibraryHandle
from .terrain import Heightfield, attach_reference, terrain_struct

FORMATS = {"png16": 0, "tiff": 1}
HURST_METHODS = {"variogram_aligned": 2, "madogram_aligned": 3}


class SchedulerUnreachable(FracterraError):
    """The Dask scheduler named by --scheduler did not answer in time."""


def _terrain(settings, reference):
    """(ft_terrain_params, buffer to keep alive) from settings by name and an optional
    reference grid (size, values)."""
    p = terrain_struct(settings)
    return p, attach_reference(p, reference)


def _format(fmt):
    if fmt not in FORMATS:
        raise InvalidArgumentError(f"the tile format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    return FORMATS[fmt]


def write_tile(col, row, settings, reference, tile, fmt, height_min, height_max, out_dir):
    """One Dask task (runs on a worker): writes tile (col, row); returns (col, row, crc32)."""
    lib = library()
    p, _keep = _terrain(settings, reference)
    crc = c_uint32()
    lib.check(lib.ft_tile_write(byref(p), tile, _format(fmt), height_min, height_max, os.fsencode(out_dir), col, row,
                                byref(crc)))
    return col, row, crc.value


def tile_height_range(col, row, settings, reference, tile):
    """One Dask task of the exact height-range pass: tile (col, row)'s (min, max)."""
    lib = library()
    p, _keep = _terrain(settings, reference)
    lo, hi = c_double(), c_double()
    lib.check(lib.ft_tile_height_range(byref(p), tile, col, row, byref(lo), byref(hi)))
    return lo.value, hi.value


def _range_union(parts):
    """Reduces [(min, max), ...] to their union (a Dask task)."""
    return min(lo for lo, _ in parts), max(hi for _, hi in parts)


class TileSet(LibraryHandle):
    """The driver's side of a tile set folder (ft_tileset*)."""

    _free = "ft_tileset_free"

    @classmethod
    def open(cls, settings, out_dir, tile=4096, fmt="png16", reference=None):
        lib = library()
        p, _keep = _terrain(settings, reference)
        out = c_void_p()
        lib.check(lib.ft_tileset_open(byref(p), tile, _format(fmt), os.fsencode(str(out_dir)), byref(out)))
        return cls(out)

    @classmethod
    def open_deferred(cls, settings, out_dir, tile=4096, fmt="png16", reference=None):
        """(set, pending): like open, but a new set needing the exact range pass is left pending
        (set_height_range gives it) instead of running that pass here."""
        lib = library()
        p, _keep = _terrain(settings, reference)
        out, pending = c_void_p(), c_int32()
        lib.check(lib.ft_tileset_open_deferred(byref(p), tile, _format(fmt), os.fsencode(str(out_dir)), byref(out),
                                               byref(pending)))
        return cls(out), bool(pending.value)

    def set_height_range(self, lo, hi):
        self._lib.check(self._lib.ft_tileset_set_height_range(self.handle, lo, hi))

    def grid(self):
        cols, rows = c_int32(), c_int32()
        self._lib.check(self._lib.ft_tileset_grid(self.handle, byref(cols), byref(rows)))
        return cols.value, rows.value

    def height_range(self):
        lo, hi = c_double(), c_double()
        self._lib.check(self._lib.ft_tileset_height_range(self.handle, byref(lo), byref(hi)))
        return lo.value, hi.value

    def done(self, col, row):
        d = c_int32()
        self._lib.check(self._lib.ft_tileset_tile_done(self.handle, col, row, byref(d)))
        return bool(d.value)

    def record(self, col, row, crc):
        self._lib.check(self._lib.ft_tileset_record(self.handle, col, row, crc))

    def finish(self):
        self._lib.check(self._lib.ft_tileset_finish(self.handle))


def manifest(folder):
    """The tile set's manifest.json as a dict (tile grid, height range, world size, tiles)."""
    path = os.path.join(str(folder), "manifest.json")
    try:
        with open(path, encoding="utf-8") as f:
            m = json.load(f)
    except (OSError, ValueError) as e:
        raise InvalidArgumentError(f"{folder} holds no readable tile set manifest ({e})") from None
    if m.get("format") != "fracterra-tileset":
        raise InvalidArgumentError(f"{path} is not a fracterra tile set manifest")
    return m


def extent(folder, lod=0):
    """(width, height): the whole set's samples per side at level of detail `lod`."""
    lib = library()
    w, h = c_int64(), c_int64()
    lib.check(lib.ft_tileset_extent(os.fsencode(str(folder)), lod, byref(w), byref(h)))
    return w.value, h.value


def read_window(folder, lod=0, x0=0, y0=0, width=None, height=None):
    """A Heightfield (close it) of the window [x0, x0 + width) x [y0, y0 + height), counted at
    level of detail `lod` (every 2^lod-th sample), read back from the tile files it touches, in
    the set's real heights; None width/height: to the end of the set."""
    lib = library()
    ew, eh = extent(folder, lod)
    width = ew - x0 if width is None else width
    height = eh - y0 if height is None else height
    out = c_void_p()
    lib.check(lib.ft_tileset_read_window(os.fsencode(str(folder)), lod, x0, y0, width, height, byref(out)))
    return Heightfield(out)


def _worker_env():
    """What each LocalCluster worker needs: this library and this package on its path."""
    package_root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
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


def exact_height_range(settings, tile, client, reference=None):
    """The exact (min, max) of the whole terrain: one Dask task per tile, reduced on Dask in
    groups of 16 (the pass the library would otherwise run serially in the driver)."""
    w, h = _extent(settings, reference)
    cols, rows = (w - 2) // tile + 1, (h - 2) // tile + 1
    tiles = [(c, r) for r in range(rows) for c in range(cols)]
    parts = client.map(tile_height_range, [c for c, _ in tiles], [r for _, r in tiles], settings=settings,
                       reference=reference, tile=tile, retries=3,
                       key=[f"fracterra-range-{c}-{r}" for c, r in tiles])
    groups = [client.submit(_range_union, parts[i:i + 16], key=f"fracterra-range-group-{i}")
              for i in range(0, len(parts), 16)]
    return client.submit(_range_union, groups, key="fracterra-range-total").result()


def build_tileset(settings, out_dir, tile=4096, fmt="png16", reference=None, client=None, scheduler=None,
                  workers=2, memory_limit="3GB", connect_timeout=10, progress=True, task_threads=1, retries=3,
                  on_tile=None):
    """Writes (or resumes) the tile set of the terrain `settings` (names as in params.TERRAIN_PARAMS,
    e.g. {"method": "MIDPOINT", "levels": 14, "hurst": 0.8}) into `out_dir`, one Dask task per tile
    still to do; a new set whose height range needs the exact pass gets it from one task per tile
    too. Returns a summary dict (tiles written and skipped, seconds, peak worker memory).
    on_tile(client, done, total), if given, is called after each recorded tile (tests kill workers there)."""
    start = time.monotonic()
    settings = dict(settings)
    settings["threads"] = task_threads
    ts, pending = TileSet.open_deferred(settings, out_dir, tile, fmt, reference)
    own = False
    with ts:
        try:
            cols, rows = ts.grid()
            summary = {"tiles": cols * rows, "columns": cols, "rows": rows}
            if pending:
                if client is None:
                    client, own = connect(scheduler, workers, memory_limit, connect_timeout), True
                t = time.monotonic()
                ts.set_height_range(*exact_height_range(settings, tile, client, reference))
                summary["range_seconds"] = time.monotonic() - t
            lo, hi = ts.height_range()
            todo = [(c, r) for r in range(rows) for c in range(cols) if not ts.done(c, r)]
            summary.update({"written": len(todo), "skipped": cols * rows - len(todo), "height_range": [lo, hi]})
            if todo:
                if client is None:
                    client, own = connect(scheduler, workers, memory_limit, connect_timeout), True
                from distributed import as_completed
                from tqdm import tqdm
                futures = client.map(write_tile, [c for c, _ in todo], [r for _, r in todo], settings=settings,
                                     reference=reference, tile=tile, fmt=fmt, height_min=lo, height_max=hi,
                                     out_dir=os.path.abspath(str(out_dir)), retries=retries,
                                     key=[f"fracterra-tile-{c}-{r}" for c, r in todo])
                with tqdm(total=len(todo), unit="tile", disable=not progress, file=sys.stderr) as bar:
                    for done, future in enumerate(as_completed(futures), 1):
                        col, row, crc = future.result()
                        ts.record(col, row, crc)
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
    summary["seconds"] = time.monotonic() - start
    return summary


def _hurst_params(method):
    lib = library()
    hp = lib.hurst_params_type()
    lib.check(lib.ft_hurst_params_init(byref(hp)))
    if method not in HURST_METHODS:
        raise InvalidArgumentError(f"the set's H needs an aligned method ({', '.join(HURST_METHODS)}), got {method!r}")
    hp.method = HURST_METHODS[method]
    return hp


def _extent(settings, reference):
    lib = library()
    p, _keep = _terrain(settings, reference)
    w, h = c_int64(), c_int64()
    lib.check(lib.ft_terrain_extent(byref(p), 0, byref(w), byref(h)))
    return w.value, h.value


def tile_increment_sums(col, row, settings, reference, tile, method):
    """One Dask task: the increment sums of tile (col, row), generated as a window (exact floats)."""
    lib = library()
    p, _keep = _terrain(settings, reference)
    w, h = _extent(settings, reference)
    x0, y0 = col * tile, row * tile
    tw, th = min(tile + 1, w - x0), min(tile + 1, h - y0)
    hp = _hurst_params(method)
    n = c_size_t()
    lib.check(lib.ft_increment_lags(byref(hp), w, h, None, 0, byref(n)))
    sums, counts = (c_double * n.value)(), (c_double * n.value)()
    out = c_void_p()
    lib.check(lib.ft_terrain_generate_window(byref(p), x0, y0, tw, th, byref(out)))
    with Heightfield(out) as window:
        lib.check(lib.ft_increment_sums(window.handle, byref(hp), x0, y0, w, h, sums, counts, n.value))
    return list(sums), list(counts)


def _add_sums(parts):
    """Reduces [(sums, counts), ...] element-wise (a Dask task)."""
    sums = [sum(v) for v in zip(*(s for s, _ in parts))]
    counts = [sum(v) for v in zip(*(c for _, c in parts))]
    return sums, counts


def hurst_from_sums(settings, sums, counts, method="variogram_aligned", reference=None):
    """H, D and the fit of the whole surface from its reduced increment sums."""
    lib = library()
    w, h = _extent(settings, reference)
    hp = _hurst_params(method)
    n = len(sums)
    r = HurstResult()
    r.struct_size = ctypes.sizeof(HurstResult)
    lib.check(lib.ft_hurst_from_increment_sums(byref(hp), w, h, (c_double * n)(*sums), (c_double * n)(*counts), n,
                                               byref(r)))
    return {"hurst": r.hurst, "dimension": r.dimension, "std_error": r.std_error, "lag_min": r.band_lo,
            "lag_max": r.band_hi, "points": r.points, "method": method}


def measure_tileset(settings, tile, client, method="variogram_aligned", reference=None):
    """H (aligned variogram or madogram) and D = 3 - H of the whole terrain, from one Dask task
    per tile (its increment sums) reduced on Dask; equals ft_hurst_heightfield of the whole
    wherever the whole fits. Lags up to the default band must divide `tile`."""
    w, h = _extent(settings, reference)
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


def _settings_parser():
    """argparse flags for every terrain setting, from the library's parameter table."""
    parser = argparse.ArgumentParser(
        prog="python3 -m fracterra.core.tiles",
        description="Write a terrain larger than memory as a tile set on Dask (one task per tile).")
    for p in params_mod.library_params("terrain"):
        flag = "--" + p.name.replace("_", "-")
        if p.kind == "enum":
            parser.add_argument(flag, dest=p.name, choices=[i[0].lower() for i in p.items], help=p.description)
        elif p.kind == "bool":
            parser.add_argument(flag, dest=p.name, action="store_const", const=True, help=p.description)
        else:
            parser.add_argument(flag, dest=p.name, type=int if p.kind == "int" else float, help=p.description)
    parser.add_argument("--tile", type=int, default=4096, help="cells per tile side (tiles hold tile + 1 samples)")
    parser.add_argument("--format", default="png16", choices=sorted(FORMATS))
    parser.add_argument("--out", required=True, help="the tile set's folder (a rerun resumes)")
    parser.add_argument("--scheduler", help="tcp://HOST:8786 of a running `dask scheduler`; default: a LocalCluster")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    parser.add_argument("--memory-limit", default="3GB", help="LocalCluster memory limit per worker")
    parser.add_argument("--connect-timeout", type=float, default=10, help="seconds to wait for --scheduler")
    parser.add_argument("--task-threads", type=int, default=1, help="library threads per task")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--measure", action="store_true",
                        help="also H (aligned variogram) and D of the whole from per-tile sums reduced on Dask")
    return parser


def main(argv=None):
    args = _settings_parser().parse_args(argv)
    names = {p.name for p in params_mod.library_params("terrain")}
    settings = {k: (v.upper() if isinstance(v, str) else v) for k, v in vars(args).items()
                if k in names and v is not None}
    try:
        client = connect(args.scheduler, args.workers, args.memory_limit, args.connect_timeout)
        try:
            summary = build_tileset(settings, args.out, args.tile, args.format, client=client,
                                    progress=not args.quiet, task_threads=args.task_threads)
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


if __name__ == "__main__":
    # Run from the package module, not from __main__: Dask pickles the tasks by
    # reference to fracterra.core.tiles, which every worker imports (functions
    # of __main__ would be pickled by value, with their ctypes globals).
    from fracterra.core import tiles as _tiles
    sys.exit(_tiles.main())
