#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tile-set benchmark of docs/scale.md: a midpoint terrain far larger than the
workers' memory written as 16-bit tiles through Dask on this machine, against the
in-memory generator in the same run.

    PYTHONPATH=build/python/stage_linux_x86_64 FRACTERRA_LIBRARY=build/native/libfracterra.so \\
        /usr/bin/python3 native/bench/tiles_dask_bench.py --levels 16 --tile 4096 \\
        --workers 2 --memory-limit 3GB --out /work/scratch/tiles65537

With --erode PRESET: an eroded set of a levels-L terrain (Dask, end to end: range pass, tiles,
manifest, mosaics, and with --engine the engine cut) against the in-memory erosion of the same
terrain (ft_terrain_build, all cores), alternated in the same run, --reps of each; with --maps
the in-memory rep also writes its heights and maps whole, as the set writes its tiles' (float32
COG), and the report has both ratios (compute alone, and with those files):

    ... tiles_dask_bench.py --erode land --levels 13 --tile 4096 --workers 2 --memory-limit 10GB \
        --reps 3 --out /work/scratch/eroded8193 [--maps --engine unreal]

Reports (JSON on stdout, medians of --reps runs where it says so):
  in-memory samples/s   ft_terrain_generate of a levels-13 terrain (8193^2), all cores, median of reps;
  generation samples/s  tile windows generated on the cluster and dropped (no encoding), the first
                        --generation-tiles tiles (default all), samples / wall time, median of reps;
  end-to-end samples/s  the tile set written (tiles, manifest, VRT, overviews) / wall time, once
                        (--write-reps for more; each rewrites the set from scratch), and of that
                        the finish (VRT and overviews, GDAL on all cores);
  peak memory per worker (ru_maxrss of each worker process), and the machine load (uptime).
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time
from ctypes import byref, c_void_p

from fracterra import tiles
from fracterra.core import generate_terrain
from fracterra.core.binding import library
from fracterra.core.terrain import terrain_struct


def generate_only(col, row, settings, tile):
    """A task: tile (col, row)'s window generated and dropped; returns its samples."""
    lib = library()
    p = terrain_struct(settings)
    w, h = tiles.terrain_extent(settings, None)
    tw, th = min(tile + 1, w - col * tile), min(tile + 1, h - row * tile)
    out = c_void_p()
    lib.check(lib.ft_terrain_generate_window(byref(p), col * tile, row * tile, tw, th, byref(out)))
    lib.ft_heightfield_free(out)
    return tw * th


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", type=int, default=16)
    ap.add_argument("--hurst", type=float, default=0.8)
    ap.add_argument("--tile", type=int, default=4096)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--memory-limit", default="3GB")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--write-reps", type=int, default=1)
    ap.add_argument("--generation-tiles", type=int, default=0, help="tiles in the generation-only pass (0: all)")
    ap.add_argument("--out", required=True, help="scratch folder for the tile set (removed first)")
    ap.add_argument("--keep", action="store_true", help="keep the tile set afterwards")
    ap.add_argument("--measure", action="store_true", help="also H and D of the whole from per-tile sums")
    ap.add_argument("--erode", help="an erosion preset (land, ...): the eroded set against the in-memory erosion")
    ap.add_argument("--maps", action="store_true", help="--erode: the set with its maps")
    ap.add_argument("--engine", help="--erode: also cut the set for this engine (unity, unreal, godot)")
    a = ap.parse_args()
    if a.erode:
        return eroded(a)
    settings = {"method": "MIDPOINT", "levels": a.levels, "hurst": a.hurst, "seed": 1, "threads": 1}
    report = {"levels": a.levels, "tile": a.tile, "workers": a.workers, "memory_limit": a.memory_limit,
              "uptime_before": subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()}

    times = []
    for _ in range(a.reps):
        t = time.perf_counter()
        with generate_terrain({"method": "MIDPOINT", "levels": 13, "hurst": a.hurst, "seed": 1}, threads=0):
            pass
        times.append(time.perf_counter() - t)
    report["in_memory_seconds_8193"] = times
    report["in_memory_samples_per_s"] = 8193.0 ** 2 / statistics.median(times)

    client = tiles.connect(workers=a.workers, memory_limit=a.memory_limit)
    try:
        w, h = tiles.terrain_extent(settings, None)
        cols, rows = (w - 2) // a.tile + 1, (h - 2) // a.tile + 1
        grid = [(c, r) for r in range(rows) for c in range(cols)]
        times = []
        part = grid[:a.generation_tiles] if a.generation_tiles else grid
        for rep in range(a.reps):
            t = time.perf_counter()
            futures = client.map(generate_only, [c for c, _ in part], [r for _, r in part], settings=settings,
                                 tile=a.tile, pure=False)
            generated = sum(client.gather(futures))
            times.append(time.perf_counter() - t)
        samples = w * h
        report["samples"] = samples
        report["generation_tiles"] = len(part)
        report["generation_seconds"] = times
        report["generation_samples_per_s"] = generated / statistics.median(times)
        report["generation_vs_in_memory"] = report["generation_samples_per_s"] / report["in_memory_samples_per_s"]

        times, summaries = [], []
        for rep in range(a.write_reps):
            shutil.rmtree(a.out, ignore_errors=True)
            t = time.perf_counter()
            summaries.append(tiles.build_tileset(settings, a.out, a.tile, client=client, progress=False))
            times.append(time.perf_counter() - t)
        report["write_seconds"] = times
        report["end_to_end_samples_per_s"] = samples / statistics.median(times)
        report["tiles"] = summaries[-1]["tiles"]
        # The manifest and the VRT mosaic with its overviews, in the driver after the tiles.
        report["finish_seconds"] = [sm["finish_seconds"] for sm in summaries]
        report["disk_bytes"] = sum(os.path.getsize(os.path.join(a.out, f)) for f in os.listdir(a.out))
        if a.measure:
            t = time.perf_counter()
            report["measure"] = tiles.measure_tileset(settings, a.tile, client)
            report["measure_seconds"] = time.perf_counter() - t
        report["worker_peak_rss_mib"] = sorted(client.run(tiles._peak_rss_mib).values())
    finally:
        cluster = client.cluster
        client.close()
        cluster.close()
        if not a.keep:
            shutil.rmtree(a.out, ignore_errors=True)
    report["uptime_after"] = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    print(json.dumps(report, indent=1))
    return 0


def _uptime():
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def _cpu_seconds():
    """This process's CPU seconds (user + system, all threads)."""
    import resource
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def _cluster_cpu_seconds(client):
    """The driver's and every worker's CPU seconds, summed."""
    return _cpu_seconds() + sum(client.run(_cpu_seconds).values())


def _write_whole(hf, maps, folder):
    """The whole's heights and maps as the set writes its tiles' (float32 GeoTIFF, COG)."""
    from fracterra.core.raster import write_heightfield
    from fracterra.core.terrain import Heightfield
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(os.path.join(folder, "maps"))
    write_heightfield(hf, os.path.join(folder, "heights.tif"))
    for name, values in maps.items():
        with Heightfield.from_values(hf.width, hf.height, values) as m:
            write_heightfield(m, os.path.join(folder, "maps", name + ".tif"))


def eroded(a):
    """The eroded set on Dask against the in-memory erosion of the same terrain, alternated."""
    from fracterra.core import build_terrain
    settings = {"method": "MIDPOINT", "levels": a.levels, "hurst": a.hurst, "seed": 1, "world_size": 10.0,
                "sigma": 1.0}
    report = {"levels": a.levels, "tile": a.tile, "workers": a.workers, "memory_limit": a.memory_limit,
              "preset": a.erode, "maps": a.maps, "engine": a.engine, "uptime_before": _uptime()}
    w, h = tiles.terrain_extent(settings, None)
    memory, dask, summaries, loads, memory_cpu, dask_cpu = [], [], [], [], [], []
    memory_write, memory_write_cpu = [], []
    client = tiles.connect(workers=a.workers, memory_limit=a.memory_limit)
    try:
        for rep in range(a.reps):
            # CPU seconds beside the wall time: on a machine shared with other sessions the wall
            # time follows their load, the CPU time much less.
            c, t = _cpu_seconds(), time.perf_counter()
            hf, maps = build_terrain(settings, preset=a.erode.upper(), maps=a.maps, threads=0)
            memory.append(time.perf_counter() - t)
            memory_cpu.append(_cpu_seconds() - c)
            if a.maps:  # and the same files as the set's, written whole: what a user of --maps keeps
                c, t = _cpu_seconds(), time.perf_counter()
                _write_whole(hf, maps, a.out + "-in-memory")
                memory_write.append(time.perf_counter() - t)
                memory_write_cpu.append(_cpu_seconds() - c)
            hf.close()
            shutil.rmtree(a.out, ignore_errors=True)
            c, t = _cluster_cpu_seconds(client), time.perf_counter()
            summaries.append(tiles.build_tileset(settings, a.out, a.tile, client=client, progress=False,
                                                 preset=a.erode.upper(), maps=a.maps, engine=a.engine))
            dask.append(time.perf_counter() - t)
            dask_cpu.append(_cluster_cpu_seconds(client) - c)
            loads.append(_uptime())
            # Each rep as it ends (stderr), so a run cut short still says what it measured.
            print(json.dumps({"rep": rep, "in_memory_seconds": memory[-1], "in_memory_cpu_seconds": memory_cpu[-1],
                              "in_memory_write_seconds": memory_write[-1] if memory_write else None,
                              "dask_seconds": dask[-1], "dask_cpu_seconds": dask_cpu[-1],
                              "range_seconds": summaries[-1].get("range_seconds"),
                              "finish_seconds": summaries[-1]["finish_seconds"],
                              "engine_seconds": summaries[-1].get("engine_seconds"), "load": loads[-1]}),
                  file=sys.stderr, flush=True)
        report["worker_peak_rss_mib"] = sorted(client.run(tiles._peak_rss_mib).values())
    finally:
        cluster = client.cluster
        client.close()
        cluster.close()
    report.update({"samples": w * h, "in_memory_seconds": memory, "dask_seconds": dask, "loads": loads,
                   "in_memory_cpu_seconds": memory_cpu, "dask_cpu_seconds": dask_cpu,
                   "in_memory_samples_per_s": w * h / statistics.median(memory),
                   "dask_samples_per_s": w * h / statistics.median(dask),
                   "range_seconds": [sm.get("range_seconds") for sm in summaries],
                   "finish_seconds": [sm["finish_seconds"] for sm in summaries],
                   "engine_seconds": [sm.get("engine_seconds") for sm in summaries]})
    report["dask_vs_in_memory"] = report["dask_samples_per_s"] / report["in_memory_samples_per_s"]
    if memory_write:
        with_files = [m + f for m, f in zip(memory, memory_write)]
        report.update({"in_memory_write_seconds": memory_write, "in_memory_write_cpu_seconds": memory_write_cpu,
                       "in_memory_with_files_seconds": with_files,
                       "dask_vs_in_memory_with_files": statistics.median(with_files) / statistics.median(dask)})
    shutil.rmtree(a.out + "-in-memory", ignore_errors=True)
    if not a.keep:
        shutil.rmtree(a.out, ignore_errors=True)
    report["uptime_after"] = _uptime()
    print(json.dumps(report, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
