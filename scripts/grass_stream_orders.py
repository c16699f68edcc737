#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A one-off measurement, not a CI test: fracterra's river network against
GRASS GIS's `r.stream.extract` on the same eroded terrain (issue 40).

Usage: grass_stream_orders.py FRACTERRA_CLI WORKDIR [LANDFORM:SEED ...]
(eroded terrains already in WORKDIR, e_LANDFORM SEED.npy, are reused)

For each landform (plain, radial falloff, falloff with 30% sea) and seed, the
terrain is made and eroded by `fracterra` (fBm 513^2, H 0.7, world size 20,
`erode --preset rugged_mountains`), then:
  - `fracterra analyze --rivers` (min_area 0.1 world units^2) gives Horton's
    ratios by Strahler streams and Hack's h;
  - GRASS 8.2's `r.stream.extract` (Debian grass-core; threshold = the same
    min_area in cells, single flow, its own depression handling) gives the
    stream raster and its flow directions, and the Strahler orders, streams
    and Horton's ratios are computed here from those rasters, independently
    of the library (`r.stream.order` is an add-on that cannot be installed
    here). The sea (the landform's flat floor) is NULL for GRASS.
Horton's ratios are fitted as the library fits them (analysis/horton.cpp):
log N_k and log mean L_k against k over orders 1 .. top - 1 (the top order's
one or two streams are left out). Prints one line per terrain.
Results: docs/rivers.md, "Horton and Hack on three landforms".
"""

import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal

gdal.UseExceptions()

SIZE, WORLD, MIN_AREA = 513, 20.0, 0.1
LANDFORMS = {
    "plain": [],
    "falloff": ["--falloff", "radial"],
    "sea": ["--falloff", "radial", "--sea", "fraction", "--sea-fraction", "0.3"],
    # An island that rises out of its edge level: -0.6 lies under every raw
    # height of seeds 1-3 (-0.57..-0.52), so no low inside the rim is below it.
    "island": ["--falloff", "radial", "--edge-level", "-0.6"],
    "island_sea": ["--falloff", "radial", "--edge-level", "-0.6", "--sea", "fraction", "--sea-fraction", "0.3"],
}
# The island with its foot plain (within 0.01 of the edge level -0.6, the
# sediment laid on it included) cut away as a sea for both tools, and our
# lakes off (GRASS routes through depressions): the networks on the island
# alone, to tell the plain's part in R_b from the rest.
LANDFORMS["island_foot"] = LANDFORMS["island"]
FOOT = -0.59
# Landforms whose sea is erosion's base level and the rivers' sea too (as the
# pipeline passes it); the older "sea" rows erode and trace it as land.
SEA_BOTH = {"island_sea": ["--sea", "fraction", "--sea-fraction", "0.3"]}
# Rivers' flags only: the terrain is eroded as its landform says.
RIVERS_ONLY = {"island_foot": ["--sea", "height", "--sea-level", str(FOOT), "--min-lake-area", "1e6"]}
# GRASS direction codes (r.stream.extract, as r.watershed): 1 NE, 2 N, 3 NW,
# 4 W, 5 SW, 6 S, 7 SE, 8 E; rows grow southwards.
STEP = {1: (-1, 1), 2: (-1, 0), 3: (-1, -1), 4: (0, -1), 5: (1, -1), 6: (1, 0), 7: (1, 1), 8: (0, 1)}


def run(args, **kw):
    r = subprocess.run(args, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(map(str, args))}\n{r.stdout}\n{r.stderr}")
    return r


def find(d, key):
    if isinstance(d, dict):
        if key in d:
            return d
        for v in d.values():
            x = find(v, key)
            if x is not None:
                return x
    return None


def horton(counts, lengths):
    top = len(counts)
    fitted = 2 if top == 2 else top - 1
    k = np.arange(1, fitted + 1)
    rb = math.exp(-np.polyfit(k, np.log(counts[:fitted]), 1)[0])
    rl = math.exp(np.polyfit(k, np.log(lengths[:fitted]), 1)[0])
    return rb, rl


def strahler_streams(stream, direction, spacing):
    """Strahler orders over the stream raster's cells, each draining to the
    stream cell its direction points at (or out); streams of order k start at
    a head (k = 1) or where two of order k - 1 meet. Returns counts and mean
    lengths per order."""
    h, w = stream.shape
    cells = np.argwhere(stream)
    index = {(int(r), int(c)): i for i, (r, c) in enumerate(cells)}
    down = np.full(len(cells), -1)
    step_len = np.zeros(len(cells))
    for i, (r, c) in enumerate(cells):
        d = int(direction[r, c])
        if d <= 0 or d not in STEP:
            continue
        dr, dc = STEP[d]
        step_len[i] = spacing * (math.sqrt(2) if dr and dc else 1.0)
        j = index.get((int(r) + dr, int(c) + dc))
        if j is not None:
            down[i] = j
    ups = [[] for _ in cells]
    for i, j in enumerate(down):
        if j >= 0:
            ups[j].append(i)
    # Topological order from the heads.
    pending = np.array([len(u) for u in ups])
    order = np.zeros(len(cells), dtype=int)
    queue = [i for i in range(len(cells)) if pending[i] == 0]
    seen = 0
    while queue:
        i = queue.pop()
        seen += 1
        up = [order[u] for u in ups[i]]
        if not up:
            order[i] = 1
        else:
            m = max(up)
            order[i] = m + 1 if up.count(m) >= 2 else m
        j = down[i]
        if j >= 0:
            pending[j] -= 1
            if pending[j] == 0:
                queue.append(j)
    assert seen == len(cells), "the stream raster's directions hold a cycle"
    top = int(order.max())
    counts = np.zeros(top)
    total = np.zeros(top)
    for i in range(len(cells)):
        k = order[i]
        if not any(order[u] == k for u in ups[i]):
            counts[k - 1] += 1  # a stream of order k starts here
        total[k - 1] += step_len[i]
    return counts, total / np.maximum(counts, 1)


def grass_network(z, sea_mask, spacing, work):
    tif = os.path.join(work, "dem.tif")
    ds = gdal.GetDriverByName("GTiff").Create(tif, z.shape[1], z.shape[0], 1, gdal.GDT_Float32)
    ds.SetGeoTransform((0, spacing, 0, z.shape[0] * spacing, 0, -spacing))
    band = ds.GetRasterBand(1)
    band.SetNoDataValue(-1e30)
    band.WriteArray(np.where(sea_mask, -1e30, z).astype(np.float32))
    ds = None
    threshold = int(round(MIN_AREA / spacing ** 2))
    script = (
        f"r.in.gdal -o input={tif} output=dem --quiet && g.region raster=dem && "
        f"r.stream.extract elevation=dem threshold={threshold} stream_raster=streams direction=dir --quiet && "
        f"r.out.gdal -c input=streams output={work}/streams.tif format=GTiff type=Int32 --quiet && "
        f"r.out.gdal -c input=dir output={work}/dir.tif format=GTiff type=Int32 --quiet"
    )
    run(["grass", "--tmp-location", "XY", "--exec", "sh", "-c", script], cwd=work)
    sds = gdal.Open(f"{work}/streams.tif")  # kept open while its band is read
    streams = sds.ReadAsArray()
    nodata = sds.GetRasterBand(1).GetNoDataValue()
    direction = gdal.Open(f"{work}/dir.tif").ReadAsArray()
    mask = (streams != nodata) & (streams > 0) if nodata is not None else streams > 0
    return strahler_streams(mask, direction, spacing)


def main():
    cli, work = sys.argv[1], os.path.abspath(sys.argv[2])  # GRASS runs in work: absolute paths
    os.makedirs(work, exist_ok=True)
    if shutil.which("grass") is None:
        sys.exit("GRASS is not installed (Debian grass-core)")
    spacing = WORLD / (SIZE - 1)
    only = sys.argv[3:]
    for name, flags in LANDFORMS.items():
        for seed in (1, 2, 3):
            if only and f"{name}:{seed}" not in only:
                continue
            made = "island" if name == "island_foot" else name  # the same terrain
            t, e = f"{work}/t_{made}{seed}.npy", f"{work}/e_{made}{seed}.npy"
            if not os.path.exists(e):
                run([cli, "terrain", "--method", "fbm", "--size", str(SIZE), "--hurst", "0.7", "--world-size", str(WORLD),
                     "--seed", str(seed), *flags, "--out", t])
                run([cli, "erode", "--in", t, "--preset", "rugged_mountains", *SEA_BOTH.get(name, []), "--out", e])
            if name in SEA_BOTH or name in RIVERS_ONLY:
                a = json.loads(run([cli, "rivers", "--in", e, "--out", f"{work}/r.json", "--stats", "--min-area",
                                    str(MIN_AREA), *SEA_BOTH.get(name, RIVERS_ONLY.get(name))]).stdout)
            else:
                a = find(json.loads(run([cli, "analyze", e, "--rivers", "--min-area", str(MIN_AREA)]).stdout),
                         "bifurcation_ratio")
            z = np.load(e).astype(np.float64)
            sea = z <= z.min() + 1e-9 if name in ("sea", "island_sea") else np.zeros(z.shape, bool)
            if name == "island_foot":
                sea = z <= FOOT
            with tempfile.TemporaryDirectory(dir=work) as g:
                counts, lengths = grass_network(z, sea, spacing, g)
            rb, rl = horton(counts, lengths)
            print(f"{name:8s} seed {seed}: fracterra R_b {a['bifurcation_ratio']:.2f} R_l {a['length_ratio']:.2f} "
                  f"h {a['hack_h']:.3f} streams {a['streams_per_order']} | GRASS r.stream.extract R_b {rb:.2f} "
                  f"R_l {rl:.2f} streams {[int(c) for c in counts]}", flush=True)


if __name__ == "__main__":
    main()
