"""Tile sets on Dask for a terrain larger than memory, one task per tile:

    python3 -m fracterra.tiles --levels 16 --tile 4096 --out DIR [--scheduler tcp://H:8786] [--measure]

The driver opens the set (fracterra.core.tiles.TileSet), runs the exact
height-range pass where one is needed as one Dask task per tile, submits one
task per tile still to do, records each finished tile's CRC-32 in the
manifest's journal as results arrive, and finishes with the VRT mosaic. A
task is pure (terrain settings, tile size, format, range, folder, column,
row -> column, row, CRC-32): each worker loads the library through the
package's binding and calls ft_tile_write, so a task lost with a killed worker
is simply run again and the set comes out byte-identical.

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
from .core.binding import ENV_VAR, library
from .core.errors import FracterraError
# The tile set handle and the tasks, re-exported: one import for a script.
from .core.tiles import (FORMATS, TileSet, extent, hurst_from_sums, manifest, read_window,  # noqa: F401
                         terrain_extent, tile_height_range, tile_increment_sums, write_tile)

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


def exact_height_range(settings, tile, client, reference=None):
    """The exact (min, max) of the whole terrain: one Dask task per tile, reduced on Dask in
    groups of 16 (the pass the library would otherwise run serially in the driver)."""
    w, h = terrain_extent(settings, reference)
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


def _settings_parser():
    """argparse flags for every terrain setting, from the library's parameter table."""
    parser = argparse.ArgumentParser(
        prog="python3 -m fracterra.tiles",
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
    # Run from the package module, not from __main__: Dask pickles the driver's
    # own reductions by reference to fracterra.tiles, which every worker imports
    # (functions of __main__ would be pickled by value, with their ctypes globals).
    from fracterra import tiles as _tiles
    sys.exit(_tiles.main())
