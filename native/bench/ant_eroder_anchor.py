# SPDX-License-Identifier: GPL-3.0-or-later
"""The speed anchor of issue 15: A.N.T. Landscape's eroder, timed in Blender.

Run headless:  blender -b --factory-startup --python native/bench/ant_eroder_anchor.py -- OUTDIR 257 513 1025
For each size N it adds an A.N.T. landscape of N x N vertices (its defaults
otherwise), saves the heights as OUTDIR/ant_N.npy (float32, N x N, rows
along y) for our eroder to erode the same grid, and times
bpy.ops.mesh.eroder(Iterations=1) with its defaults (30 river, 5 avalanche,
5 diffuse passes) three times on fresh landscapes. Prints one JSON line per
size: the three wall times and their median.
"""

import json
import statistics
import sys
import time

import addon_utils
import bpy
import numpy as np


def landscape(n):
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob)
    bpy.ops.mesh.landscape_add(subdivision_x=n, subdivision_y=n, refresh=True)
    return bpy.context.active_object


def heights(ob, n):
    co = np.empty(len(ob.data.vertices) * 3, dtype=np.float32)
    ob.data.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3)
    order = np.lexsort((co[:, 0], co[:, 1]))  # rows along y, x within a row
    return co[order, 2].reshape(n, n), float(co[:, 0].max() - co[:, 0].min())


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    out, sizes = argv[0], [int(s) for s in argv[1:]]
    addon_utils.enable("ant_landscape", default_set=True)
    for n in sizes:
        times = []
        for rep in range(3):
            ob = landscape(n)
            if rep == 0:
                z, extent = heights(ob, n)
                np.save(f"{out}/ant_{n}.npy", z)
            bpy.context.view_layer.objects.active = ob
            t0 = time.perf_counter()
            bpy.ops.mesh.eroder(Iterations=1)
            times.append(time.perf_counter() - t0)
        print(json.dumps({"size": n, "extent": extent, "seconds": times, "median": statistics.median(times)}),
              flush=True)


main()
