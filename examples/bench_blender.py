# SPDX-License-Identifier: GPL-3.0-or-later
"""Times fracterra against Blender's bundled A.N.T. Landscape in one Blender process.

    blender -b --factory-startup --python examples/bench_blender.py -- [--repeat 3] [--levels 10]

Both add-ons build a grid of about a million vertices (ours 1025^2 at levels
10, A.N.T. 1024^2 subdivisions), then regenerate it from new settings (ours:
Regenerate, which rewrites heights in place; A.N.T.: its Refresh operator).
Prints the best and the median of `--repeat` runs of each and the ratios of
the medians, as wall-clock
time and as the process's CPU time (on a machine shared with other work the
CPU time is the steadier figure; with --threads 1 it is close to the wall time
of an idle machine). Uses the installed
fracterra add-on, or the source tree with build/native/libfracterra.so.
"""

import argparse
import statistics
import sys
import time
from pathlib import Path

import addon_utils
import bpy

sys.path.insert(0, str(Path(__file__).resolve().parent))


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="bench_blender.py")
    p.add_argument("--repeat", type=int, default=3, help="runs of each measurement (default 3)")
    p.add_argument("--levels", type=int, default=10, help="fracterra levels: 2^levels + 1 per side (default 10)")
    p.add_argument("--ant-subdivisions", type=int, default=1024, help="A.N.T. vertices per side (default 1024)")
    p.add_argument("--warmup", type=int, default=1,
                   help="untimed adds of each before the timed runs (default 1: imports, the material, first-touch memory)")
    p.add_argument("--skip-ant", action="store_true", help="time fracterra only")
    p.add_argument("--threads", type=int, default=None,
                   help="fracterra's Threads preference (0: all cores; default: the preference, 1)")
    p.add_argument("--library", help="libfracterra.so when running from the source tree")
    return p.parse_args(argv)


def clear():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def timed(fn):
    # Flush pending depsgraph work first, so each figure is the operator plus the one
    # evaluation of its result that Blender runs after it (what a user waits for).
    bpy.context.view_layer.update()
    t0, c0 = time.perf_counter(), time.process_time()
    result = fn()
    dt, dc = time.perf_counter() - t0, time.process_time() - c0
    if result != {"FINISHED"}:
        raise RuntimeError(f"operator returned {result}")
    return dt, dc


def bench_fracterra(args, rounds):
    from fracterra.blender.build import terrain as terrain_build
    from fracterra.core import params
    add, regen, own_add, own_regen = [], [], [], []
    for i in rounds:
        clear()
        add.append(timed(lambda: bpy.ops.mesh.fracterra_terrain_add(levels=args.levels, seed=1 + i)))
        obj = bpy.context.active_object
        obj.fracterra_terrain.seed = 100 + i
        regen.append(timed(bpy.ops.object.fracterra_terrain_regenerate))
        vertices = len(obj.data.vertices)
        if i == 0:
            args.defaults = params.values_of(obj.fracterra_terrain)
        # fracterra's own share: generation and mesh filling, without Blender's depsgraph.
        values = params.values_of(obj.fracterra_terrain)
        t0, c0 = time.perf_counter(), time.process_time()
        mesh, _ = terrain_build.new_terrain_mesh(values, bpy.context)
        own_add.append((time.perf_counter() - t0, time.process_time() - c0))
        bpy.data.meshes.remove(mesh)
        obj.fracterra_terrain.seed = 200 + i
        t0, c0 = time.perf_counter(), time.process_time()
        terrain_build.regenerate_object(obj, bpy.context)
        own_regen.append((time.perf_counter() - t0, time.process_time() - c0))
    return vertices, add, regen, own_add, own_regen


def bench_blender_share(args, rounds):
    """Blender's own share of an add: the same mesh (UV map, colours, height and
    slope attributes) from arrays the library made beforehand, timed from the
    new mesh to the view-layer update after it is linked, the arrays freed
    before the update as in the operator. No add-on can build this mesh for
    less in this Blender; the add's time less this is fracterra's."""
    from fracterra.blender.build import mesh as mesh_build, splat_material
    from fracterra.blender.build.terrain import terrain_work
    times = []
    for i in rounds:
        clear()
        values = dict(args.defaults)  # the first add's settings: the add-on's defaults
        values["seed"] = 300 + i
        g = terrain_work(values, bpy.context)(lambda _fraction: False)
        bpy.context.view_layer.update()
        t0, c0 = time.perf_counter(), time.process_time()
        mesh = bpy.data.meshes.new("Blender's share")
        mesh_build.fill_grid_mesh(mesh, g, smooth=values["smooth"])
        mesh_build.set_height_slope(mesh, g.height, g.slope)
        splat_material.set_colors(mesh, g.colors)
        del g
        bpy.context.collection.objects.link(bpy.data.objects.new("Blender's share", mesh))
        bpy.context.view_layer.update()
        times.append((time.perf_counter() - t0, time.process_time() - c0))
    return times


def bench_ant(args, rounds):
    add, refresh = [], []
    n = args.ant_subdivisions
    vertices = 0
    for i in rounds:
        clear()
        add.append(timed(lambda: bpy.ops.mesh.landscape_add(
            subdivision_x=n, subdivision_y=n, random_seed=i, refresh=True)))
        obj = bpy.context.active_object
        obj.ant_landscape.random_seed = 100 + i
        refresh.append(timed(bpy.ops.mesh.ant_landscape_refresh))
        vertices = len(obj.data.vertices)
    return vertices, add, refresh


def line(name, vertices, times):
    wall, cpu = [t[0] for t in times], [t[1] for t in times]
    return (f"{name:<34} {vertices:>9,d} verts  wall best {min(wall):7.3f} s median {statistics.median(wall):7.3f} s"
            f"  cpu best {min(cpu):7.3f} s median {statistics.median(cpu):7.3f} s"
            f"  (wall: {' '.join(f'{t:.3f}' for t in wall)})")


def median(times, i):
    return statistics.median(t[i] for t in times)


def main():
    args = parse_args()
    from importlib import import_module
    demo = import_module("20_blender_scene")
    print(f"bench: fracterra from the {demo.enable_addon(args.library)}")
    import fracterra.core as core
    ok, status = core.status()
    if not ok:
        raise RuntimeError(status)
    from fracterra.blender.common.preferences import preferences
    prefs = preferences(bpy.context)
    if prefs is not None and args.threads is not None:
        prefs.threads = args.threads
    threads = prefs.threads if prefs is not None else 0
    if not args.skip_ant and addon_utils.enable("ant_landscape", default_set=False, handle_error=None) is None:
        raise RuntimeError("could not enable ant_landscape (it needs Debian's python3-numpy)")
    # One round at a time, ours then A.N.T.'s: on a machine shared with other
    # work a change of load then falls on both sides alike.
    for i in range(args.warmup):
        clear()
        bpy.ops.mesh.fracterra_terrain_add(levels=args.levels, seed=1000 + i)
        if not args.skip_ant:
            clear()
            n = args.ant_subdivisions
            bpy.ops.mesh.landscape_add(subdivision_x=n, subdivision_y=n, random_seed=1000 + i, refresh=True)
    add, regen, own_add, own_regen, share, aadd, arefresh = [], [], [], [], [], [], []
    for i in range(args.repeat):
        v, *ours = bench_fracterra(args, [i])
        for into, got in zip((add, regen, own_add, own_regen), ours):
            into += got
        share += bench_blender_share(args, [i])
        if not args.skip_ant:
            av, a, r = bench_ant(args, [i])
            aadd += a
            arefresh += r
    rows = [line("fracterra Add Fractal Terrain", v, add), line("fracterra Regenerate (in place)", v, regen),
            line("  fracterra work only: add", v, own_add), line("  fracterra work only: regenerate", v, own_regen),
            line("  Blender's share of an add", v, share)]
    if not args.skip_ant:
        rows += [line("A.N.T. Landscape add", av, aadd), line("A.N.T. Landscape Refresh", av, arefresh)]
        for what, ours, theirs in (("add", add, aadd), ("refresh", regen, arefresh)):
            rows.append(f"ratio {what:<8} A.N.T. / fracterra = {median(theirs, 0) / median(ours, 0):6.1f}x wall, "
                        f"{median(theirs, 1) / median(ours, 1):6.1f}x cpu (medians)")
    print(f"bench: Blender {bpy.app.version_string}, {status}, threads {threads or 'all'}, "
          f"{args.repeat} runs each")
    for r in rows:
        print("bench:", r)


if __name__ == "__main__":
    try:
        main()
    except Exception as e:
        import os
        import traceback
        traceback.print_exc()
        print(f"bench_blender: error: {e}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)
