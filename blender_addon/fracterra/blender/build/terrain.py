# SPDX-License-Identifier: GPL-3.0-or-later
"""From settings to a terrain mesh: reference points, generation and mesh
building as progress.Jobs (a new mesh, or an existing one rewritten in place)."""

import array
import math
import time

import bpy
import numpy as np
from mathutils import Matrix

from ...core import params, raster
from ...core.grid import NO_FLOOR, GridArrays, grid_arrays, grid_size, height_slope, vertices
from ...core.mesh_limits import check_grid
from ...core.params import grid_shape
from ...core.resample import dyadic_levels, resample_bilinear
from . import erosion as erosion_ui
from . import erosion_masks
from . import falloff_mask
from . import mesh as mesh_build
from . import planet as planet_build
from . import splat_material
from . import children
from . import kept_final
from . import water as water_build
from .objects import mesh_level, remember_settings
from ..common.images import image_luminance
from ..common.preferences import library_threads
from ..common.jobs import Job, run_job, run_timed
from ..common.reporting import SettingsError


def _float_array(values):
    """array.array('f') of a numpy array, for the binding (which copies from a buffer)."""
    out = array.array("f")
    out.frombytes(np.ascontiguousarray(values, dtype=np.float32).tobytes())
    return out


def reference_from_object(name):
    """(size, heights) from a mesh whose vertices form a (2^m + 1)^2 grid.

    Heights are local z; vertices are ordered by y, then x, so any grid
    (Add > Mesh > Grid, a fracterra terrain, an imported survey) works.
    """
    obj = bpy.data.objects.get(name) if name else None
    if obj is None or obj.type != "MESH":
        raise SettingsError(f"Reference: choose a mesh object for 'Grid Object' (got {name or 'nothing'!r})")
    mesh = obj.data
    n = len(mesh.vertices)
    size = math.isqrt(n)
    if size * size != n or dyadic_levels(size) < 1:
        raise SettingsError(
            f"Reference object '{obj.name}' has {n} vertices; a reference grid needs (2^m + 1)^2 vertices "
            f"(9, 25, 81, 289, 1089, ...), e.g. Add > Mesh > Grid with 8 x 8 subdivisions (9 x 9 vertices)")
    co = np.empty(3 * n, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    co = co.reshape(n, 3)
    order = np.lexsort((co[:, 0], co[:, 1]))  # by y, then x; stable, as sorted() was
    return size, _float_array(co[order, 2])


def reference_from_image(name, levels, height):
    """(size, heights): the image's luminance resampled bilinearly to (2^levels + 1)^2
    points; white is `height`. Image row 0 (the bottom) is y = 0, as in the terrain."""
    size = 2 ** levels + 1
    return size, _float_array(height * resample_bilinear(image_luminance(name, "Reference"), size))


def reference_from_dem(path, levels, world_size, relief):
    """(size, heights): a DEM file (GDAL; holes filled) resampled bilinearly to
    (2^levels + 1)^2 points, north up (row 0 is the south edge, y = 0), its
    lowest point at 0. Georeferenced DEMs keep their true proportions: heights
    scale by world_size / the DEM's extent; others get `relief` from lowest to highest."""
    if not path:
        raise SettingsError("Reference: choose a DEM file for 'DEM File'")
    path = bpy.path.abspath(path)
    with raster.read_heightfield(path, nodata="FILL") as dem:
        w, h, dem_world = dem.width, dem.height, dem.world_size
        z = np.frombuffer(dem.to_array(), dtype=np.float32).reshape(h, w)[::-1].astype(np.float64)
    z -= z.min()
    top = z.max()
    scale = world_size / dem_world if dem_world > 0 else (relief / top if top > 0 else 0.0)
    size = 2 ** levels + 1
    return size, _float_array(scale * resample_bilinear(z, size))


def reference_for(values):
    if values["method"] not in params.DYADIC_METHODS:
        return None
    source = values["reference_source"]
    if source == "OBJECT":
        return reference_from_object(values["reference_object"])
    if source == "IMAGE":
        return reference_from_image(values["reference_image"], values["reference_levels"],
                                    values["reference_height"])
    if source == "DEM":
        return reference_from_dem(values["reference_file"], values["reference_levels"], values["world_size"],
                                  values["reference_height"])
    return None


def terrain_work(values, context, topology=True, frame=None, terrain_name=None):
    """The bpy-free half of a terrain job: work(progress) -> core.grid.GridArrays.

    What needs Blender happens here first, in the main thread: a grid that
    Blender cannot hold is refused before any memory is taken, and the
    reference and the falloff mask are read (a mask object is projected on
    the terrain's footprint at `frame`, its world matrix; `terrain_name`: the
    terrain object, refused as its own mask). `topology`: False when only the
    vertex positions are needed (an in-place rewrite). The erosion mask and
    the rain map are read too (from the terrain's own vertex groups, or
    images); `work.maps` holds them (erosion_masks.maps_for). The Material Rules
    file is read and checked here too (a bad one is refused before the job).
    """
    check_grid(*grid_shape(values))
    reference = reference_for(values)
    mask = falloff_mask.mask_for(values, frame if frame is not None else Matrix.Identity(4),
                                 context.evaluated_depsgraph_get(), terrain_name)
    maps = erosion_masks.maps_for(values, bpy.data.objects.get(terrain_name) if terrain_name else None)
    rules = splat_material.rules_of(values)
    threads = library_threads(context)
    # The library flattens the sea itself (ft_terrain_params.sea): no floor here.
    world_size, floor = values["world_size"], NO_FLOOR

    def grid_of(hf, progress=None):
        """The mesh arrays, then the height and slope attributes (here, in the
        worker: 4.6 s of a 4097^2 build in Blender's main thread before)."""
        report = progress or (lambda _fraction: None)
        if topology:
            g = grid_arrays(hf, world_size, floor, uvs=values["uvs"], progress=lambda f: report(0.5 * f))
        else:
            g = GridArrays(hf.width, hf.height)
            g.co = vertices(hf, *grid_size(world_size, g.nx, g.ny), floor)
        g.height, g.slope = height_slope(g.co, g.nx, g.ny, progress=lambda f: report(0.5 + 0.5 * f))
        return g

    def work(progress):
        # Generation, then the Erode step when the settings ask for it.
        return erosion_ui.generate_and_erode(values, reference, progress, threads, grid_of, falloff_mask=mask,
                                             maps=maps, rules=rules)
    work.maps = maps
    return work


def _build_new_mesh(g, values, name, settings=None):
    """Build steps of a new mesh datablock; removed again if cancelled or failed.
    `settings`: what the mesh records it was built from (its Preview is built
    from `values`, its settings are the Final's); `values` when None."""
    mesh = bpy.data.meshes.new(name)
    try:
        yield from mesh_build.fill_grid_mesh_steps(mesh, g, smooth=values["smooth"])
        # Steps of their own: at 4097^2 the attributes and the maps took 12 s
        # in one step, the bar standing still (the height and slope, 4.6 s of
        # it, are now computed in the worker; the colours and maps in one
        # step took 2.5-2.9 s at load 4-6).
        yield 0.9
        mesh_build.set_height_slope(mesh, g.height, g.slope)
        yield 0.93
        erosion_ui.set_maps(mesh, g.erosion_maps)
        yield 0.96
        splat_material.set_colors(mesh, g.colors)
        remember_settings(mesh, settings if settings is not None else values)
    except BaseException:  # GeneratorExit too: a cancel leaves nothing behind
        bpy.data.meshes.remove(mesh)
        raise
    water_build.remember(mesh, _water_of(g))  # built once the operator has made its object
    return mesh, f"{g.nx} x {g.ny} vertices"


def _water_of(g):
    """(WaterArrays, heights (ny, nx)) of a built grid, or None without Rivers and Lakes."""
    water = getattr(g, "water", None)
    if water is None:
        return None
    return water, np.frombuffer(g.co, dtype=np.float32)[2::3].reshape(g.ny, g.nx)


def build_water(obj, pending):
    """The water objects of terrain `obj` from _water_of's value (None: removes them); a summary."""
    return water_build.build_water(obj, *pending) if pending is not None else water_build.build_water(obj, None)


def new_terrain_job(values, context, name="Fractal Terrain", frame=None, preview=False):
    """A progress.Job whose value is (mesh, summary): a new mesh holding the terrain of
    `values` (its Preview when `preview`), for an object at `frame` (its world
    matrix: where a mask object is seen)."""
    built = params.preview_values(values) if preview else values
    work = terrain_work(built, context, frame=frame)
    return Job("Generating terrain", work, lambda g: _build_new_mesh(g, built, name, values))


def new_terrain_mesh(values, context, name="Fractal Terrain", frame=None):
    """(mesh, summary), built here and now (scripts, benchmarks)."""
    t0 = time.perf_counter()
    mesh, summary = run_job(new_terrain_job(values, context, name, frame))
    return mesh, f"{summary} in {time.perf_counter() - t0:.2f} s"


def _rewrite(mesh, g, values, settings):
    """The same grid: every position and attribute rewritten, one step each."""
    mesh_build.rewrite_positions(mesh, g.co)
    mesh_build.set_height_slope(mesh, g.height, g.slope)
    erosion_ui.set_maps(mesh, g.erosion_maps)
    splat_material.set_colors(mesh, g.colors)
    if values["uvs"] != (mesh.uv_layers.get(mesh_build.UV_NAME) is not None):
        mesh_build.set_uvs(mesh, g.uv if values["uvs"] else None)
    mesh_build.set_smooth(mesh, values["smooth"])
    remember_settings(mesh, settings)


def _build_in_place(obj, g, values, settings, groups, plan):
    """Build steps of a regenerated terrain (`plan`: regenerate_job's Plan). Its
    children's new curves are made aside first. Then the mesh: the same grid
    (the object's, or the kept Final's for Build Final) is rewritten in one
    step; another grid is built aside and swapped in at the end, so a cancel
    never leaves the object half-built; `groups` ({name: weights},
    erosion_masks.carried_groups) are painted onto it. A Preview over a Final
    keeps the Final (kept_final.py)."""
    made = yield from children.build_steps(g.children, settings, g.nx, g.ny)
    try:
        target = plan.target
        if len(target.vertices) == g.vertex_count and len(target.polygons) == g.face_count:
            _rewrite(target, g, values, settings)
            if target is not obj.data:  # the kept Final, rewritten: back on the object
                kept_final.bring_back(obj)
                erosion_masks.carry_groups(obj, groups or {}, g.nx, g.ny)
            elif plan.final:
                kept_final.drop(obj)
            summary = f"{g.nx} x {g.ny} terrain heights rewritten"
            water = _water_of(g)
        else:
            name = f"{obj.data.name} Preview" if plan.keep else obj.data.name
            new, _summary = yield from _build_new_mesh(g, values, name, settings)
            water = water_build.take(new)
            if plan.keep:
                kept_final.keep(obj)
            elif plan.final:
                kept_final.drop(obj)
            mesh_build.swap_mesh(obj, new)
            splat_material.give_material(obj.data)  # the old eroded material, carried over, gives way
            erosion_masks.carry_groups(obj, groups or {}, g.nx, g.ny)
            summary = f"{g.nx} x {g.ny} terrain mesh rebuilt"
    except BaseException:
        for _name, data, _extra in made:
            bpy.data.curves.remove(data)
        raise
    summary = _with_water(summary, build_water(obj, water))
    return _with_water(summary, children.commit(made))


def _with_water(summary, water):
    return f"{summary}; {water}" if water else summary


class Plan:
    """What a regenerate builds into: `target` the mesh rewritten when its grid
    is the new one (the object's, or its kept Final's for a Final), `keep` True
    when a Preview is built over the Final the object holds (kept beside it),
    `final` True when the Final itself is built."""

    def __init__(self, obj, settings, values):
        self.final = values is settings
        nx, ny = grid_shape(values)
        mesh, kept = obj.data, kept_final.kept(obj)
        level = mesh_level(obj)
        self.keep = (not self.final and kept is None and level is not None and level[0] == "Final"
                     and len(mesh.vertices) != nx * ny)
        self.target = kept if self.final and kept is not None and len(kept.vertices) == nx * ny else mesh
        if self.keep:
            self.target = None
        self.same_grid = self.target is not None and len(self.target.vertices) == nx * ny and \
            len(self.target.polygons) == (nx - 1) * (ny - 1)
        if self.target is None:
            self.target = mesh  # never its grid: a new mesh is built
        self.adds_uvs = values["uvs"] and self.target.uv_layers.get(mesh_build.UV_NAME) is None


def regenerate_job(obj, context, preview=False):
    """A progress.Job that regenerates terrain object `obj` from its stored
    settings (at its Preview level when `preview`), and its children with it
    (children.py); its value is a summary. When the grid size is unchanged
    only the vertex positions are rewritten."""
    settings = params.values_of(obj.fracterra_terrain)
    values = params.preview_values(settings) if preview else settings
    plan = Plan(obj, settings, values)
    inner = terrain_work(values, context, topology=not plan.same_grid or plan.adds_uvs,
                         frame=obj.matrix_world.copy(), terrain_name=obj.name)
    follow = children.plan(obj)
    threads = library_threads(context)

    def work(progress):
        g = inner(lambda f: progress(CHILDREN_FROM * f))
        g.children = children.remake(follow, g, values["world_size"], threads)
        return g
    label = "Regenerating terrain (Preview)" if not plan.final else "Regenerating terrain"
    groups = erosion_masks.carried_groups(values, inner.maps)
    return Job(label, work, lambda g: _build_in_place(obj, g, values, settings, groups, plan))


# The work's bar: the terrain, then its children (coastlines, a bolt: short).
CHILDREN_FROM = 0.97


def regenerate_object(obj, context, preview=False):
    """Regenerates a terrain object here and now (auto-update, scripts); returns a summary."""
    return run_timed(regenerate_job(obj, context, preview))


def preview_regenerate(obj, context):
    """Auto Update's rebuild: the terrain at its Preview level."""
    return regenerate_object(obj, context, preview=True)


@bpy.app.handlers.persistent
def final_for_render(*_args):
    """render_pre: a command-line render (blender -b -f) renders each terrain at
    its Final level, rebuilt here when its mesh holds the Preview (and each planet). Only in
    background Blender: there render_pre runs in the main thread before the
    scene is read. In the window, F12 calls it from the render job's own thread,
    where rebuilding a mesh is not safe; the sidebar says Preview then."""
    if not bpy.app.background:
        return
    for obj in list(bpy.data.objects):
        if obj.type == "MESH" and obj.fracterra_terrain.is_terrain:
            level = mesh_level(obj)
            if level is not None and level[0] == "Preview":
                print(f"fracterra: {obj.name}: building the Final level for the render", flush=True)
                regenerate_object(obj, bpy.context)
    for obj in planet_build.planets_at_preview():  # planets alike
        print(f"fracterra: {obj.name}: building the Final level for the render", flush=True)
        planet_build.regenerate_object(obj, bpy.context)
