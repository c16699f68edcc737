#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The compute of an eroded tile set with maps, without its files (docs/measurements/scale.md):

    eroded_maps_task.py LEVELS TILE whole         the whole with every map in memory, 2 threads
    eroded_maps_task.py LEVELS TILE C,R [C,R ...] tiles (C, R) of TILE (TILE + 1 samples each), every
                                                  map, 1 thread (a Dask worker's), one after another

A midpoint terrain, seed 3, Rugged Mountains. Prints the wall time and the process's peak RSS."""
import resource
import sys
import time

import fracterra.pipeline as fp


def main():
    levels, tile, what = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3:]
    settings = dict(method="midpoint", levels=levels, seed=3, erode="land")
    t0 = time.time()
    if what == ["whole"]:
        fp.terrain(maps=True, threads=2, **settings)
    else:
        for cr in what:
            c, r = (int(v) for v in cr.split(","))
            fp.window(c * tile, r * tile, tile + 1, tile + 1, maps=True, threads=1, **settings)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"levels {levels}, {' '.join(what)}: {time.time() - t0:.1f} s, peak {peak:.0f} MiB")


if __name__ == "__main__":
    main()
