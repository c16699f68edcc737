# SPDX-License-Identifier: GPL-3.0-or-later
"""From settings to a planet object: the library's closed cube-sphere as a
smooth mesh in scene units, its sea sphere (a child, water.py's SEA kind) and
its material by height, slope and latitude, as progress.Jobs (a new mesh, or
an object's regenerated in place, as terrains are)."""

import math

import bpy
import numpy as np

from ...core import params
from ...core import planet as planet_core
from . import mesh as mesh_build
from . import water as water_build
from .objects import is_planet, mesh_level, remember_settings
from .shader_nodes import NodeMaterial
from ..common.jobs import Job, run_timed
from ..common.preferences import library_threads

# The planet material's colours (linear RGB) and the slope range over which
# rock takes over (fracterra_slope, 0..1): the terrain's old eroded material's,
# kept here when terrains moved to the splat rules' colours.
GRASS, SEDIMENT, ROCK = (0.16, 0.26, 0.07), (0.55, 0.47, 0.33), (0.33, 0.31, 0.29)
STEEP = (0.3, 0.45)

MATERIAL_NAME = "Fracterra Planet"
# The sea sphere is a cube-sphere of this level (24 576 quads) whatever the
# planet's: a sphere needs no more to look round, and its faces are lifted
# so that none dips under the sea's height (sea_scale).
SEA_LEVEL = 6
# The material's rule (planet_material), the POV-Ray scene's (ft_planet.inc's
# FT_Planet): snow where the height above the sea (0..1 of the highest land)
# plus POLAR_GAIN x (|sin latitude| - POLAR_FROM) passes SNOW; so the snow
# line falls from the highest peaks at 46 degrees to the shore near the poles.
HIGHLAND = (0.25, 0.6)  # grass to bare highland over these heights
SNOW = (0.85, 0.95)
POLAR_FROM, POLAR_GAIN = 0.72, 3.0
SNOW_WHITE = (0.9, 0.92, 0.95, 1.0)


class PlanetArrays:
    """What the worker thread hands to the build: co (scene units, 3 floats per
    vertex), loop_vertices (4 per quad, or None), height (0 at the sea or the
    lowest ground, 1 at the highest), level, sea_radius (scene units, or None),
    sea_co (the sea sphere's vertices and quads, or None), sea_height (metres)."""


def scene_scale(values):
    """Scene units per metre of the planet (its Radius becomes Scene Radius)."""
    return values["scene_radius"] / values["radius"]


def sea_scale(level):
    """How much a cube-sphere of `level` on a sphere must be enlarged so that no
    face dips under the sphere: its widest quads (at the face centres) span
    2 sqrt(2) / 2^level radians corner to corner, their centres sag by
    1 - cos(sqrt(2) / 2^level)."""
    return 1.0 / math.cos(math.sqrt(2.0) / 2 ** level)


def planet_work(values, context, topology=True):
    """The bpy-free half of a planet job: work(progress) -> PlanetArrays.
    `topology`: False when only the positions are needed (an in-place rewrite)."""
    threads = library_threads(context)
    level = values["level"]

    def work(progress):
        r = PlanetArrays()
        r.level = level
        # A sea given as a fraction is a quantile over 2^16 points: found once
        # here, then given to the mesh as its height (the same flattening).
        r.sea_height = planet_core.sea_height(values)
        sea = {"sea": "HEIGHT", "sea_level": r.sea_height} if r.sea_height is not None else {}
        m = planet_core.planet_mesh({**values, **sea}, level, values["vertical_scale"], threads,
                                    lambda f: progress(0.85 * f), topology)
        k = scene_scale(values)
        r.co = (np.frombuffer(m.co, dtype=np.float32) * k).astype(np.float32)
        r.loop_vertices = m.loop_vertices
        heights = np.frombuffer(m.heights, dtype=np.float32).astype(np.float64)
        base = r.sea_height if r.sea_height is not None else float(heights.min())
        span = float(heights.max()) - base
        r.height = np.clip((heights - base) / span, 0.0, 1.0) if span > 0 else np.zeros_like(heights)
        r.sea_radius = r.sea_co = None
        if r.sea_height is not None and values["sea_sphere"]:
            r.sea_radius = k * (values["radius"] + values["vertical_scale"] * r.sea_height)
            sphere = planet_core.planet_mesh({**values, "sea": "NONE"}, SEA_LEVEL, 0.0, threads)
            unit = np.frombuffer(sphere.co, dtype=np.float32) / values["radius"]
            r.sea_co = ((unit * (r.sea_radius * sea_scale(SEA_LEVEL))).astype(np.float32), sphere.loop_vertices)
        progress(1.0)
        return r
    return work


def _slope(mesh, co):
    """The angle between each vertex normal and the radial direction, over 90
    degrees (0 flat, 1 vertical): the terrain's fracterra_slope on a sphere."""
    normals = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("normal", normals)
    n = normals.reshape(-1, 3).astype(np.float64)
    p = np.asarray(co, dtype=np.float64).reshape(-1, 3)
    radial = p / np.maximum(np.linalg.norm(p, axis=1, keepdims=True), 1e-30)
    return np.arccos(np.clip(np.einsum("ij,ij->i", n, radial), -1.0, 1.0)) / (np.pi / 2)


def _set_attributes(mesh, r):
    mesh_build.set_point_attributes(mesh, {mesh_build.HEIGHT_ATTRIBUTE: r.height,
                                           mesh_build.SLOPE_ATTRIBUTE: _slope(mesh, r.co)})


def _summary(r):
    n = len(r.co) // 3
    sea = f", sea at {r.sea_height:.0f} m" if r.sea_height is not None else ""
    return f"level {r.level}, {n:,} vertices{sea}"


def _build_new_mesh(r, name, settings):
    """Build steps of a new planet mesh; removed again if cancelled or failed."""
    mesh = bpy.data.meshes.new(name)
    try:
        yield from mesh_build.fill_quad_mesh_steps(mesh, r.co, r.loop_vertices)
        yield 0.8
        _set_attributes(mesh, r)
        mesh.materials.append(planet_material())
        remember_settings(mesh, settings)
    except BaseException:  # GeneratorExit too: a cancel leaves nothing behind
        bpy.data.meshes.remove(mesh)
        raise
    water_build.remember(mesh, r.sea_co)  # built once the operator has made its object
    return mesh, _summary(r)


def build_sea(planet, sea_co):
    """The planet's sea sphere from (vertices, quads) (None: removes it): one
    child of water.py's SEA kind with the water material; a summary."""
    if sea_co is None:
        water_build.remove_water(planet)
        return ""
    mesh = bpy.data.meshes.new(f"{planet.name} Sea")
    mesh_build.fill_quad_mesh(mesh, *sea_co)
    collection = planet.users_collection[0] if planet.users_collection else bpy.context.collection
    water_build.put(planet, "SEA", mesh.name, mesh, collection)
    return "the sea sphere"


def new_planet_job(values, context, name="Fractal Planet", preview=False):
    """A progress.Job whose value is (mesh, summary): a new mesh holding the
    planet of `values` (its Preview when `preview`)."""
    built = params.planet_preview_values(values) if preview else values
    return Job("Generating planet", planet_work(built, context), lambda r: _build_new_mesh(r, name, values))


def _build_in_place(obj, r, settings):
    """Build steps of a regenerated planet: the same level rewrites the
    positions in one step; another builds a new mesh aside and swaps it in at
    the end, so a cancel never leaves the object half-built."""
    mesh = obj.data
    if r.loop_vertices is None:
        mesh_build.rewrite_positions(mesh, r.co)
        _set_attributes(mesh, r)
        remember_settings(mesh, settings)
        summary = f"{_summary(r)}, heights rewritten"
    else:
        new, summary = yield from _build_new_mesh(r, mesh.name, settings)
        water_build.take(new)
        mesh_build.swap_mesh(obj, new)
        summary = f"{summary}, mesh rebuilt"
    sea = build_sea(obj, r.sea_co)
    return f"{summary}; {sea}" if sea else summary


def regenerate_job(obj, context, preview=False):
    """A progress.Job that regenerates planet object `obj` from its stored
    settings (at its Preview level when `preview`); its value is a summary."""
    settings = params.values_of(obj.fracterra_planet, params.PLANET_OBJECT_PARAMS)
    values = params.planet_preview_values(settings) if preview else settings
    vertices, _quads = planet_core.mesh_counts(values["level"])
    same = len(obj.data.vertices) == vertices
    label = "Regenerating planet (Preview)" if values is not settings else "Regenerating planet"
    return Job(label, planet_work(values, context, topology=not same), lambda r: _build_in_place(obj, r, settings))


def regenerate_object(obj, context, preview=False):
    """Regenerates a planet object here and now (Auto Update, scripts); returns a summary."""
    return run_timed(regenerate_job(obj, context, preview))


def preview_regenerate(obj, context):
    """Auto Update's rebuild: the planet at its Preview level."""
    return regenerate_object(obj, context, preview=True)


def planet_of(obj):
    """The planet whose settings the sidebar shows for `obj`: `obj` itself, or
    the planet its sea sphere belongs to (its parent); None."""
    if is_planet(obj):
        return obj
    if obj is not None and obj.get("fracterra_kind") == "SEA" and is_planet(obj.parent):
        return obj.parent
    return None


def planets_at_preview():
    """The planet objects whose mesh holds their Preview (final_for_render's)."""
    return [obj for obj in bpy.data.objects
            if is_planet(obj) and (mesh_level(obj) or ("",))[0] == "Preview"]


def planet_material():
    """The node material of planets (made once per file): grass on the lowland,
    bare highland above, rock where steep, and snow above a line that falls
    towards the poles (the latitude from the shading point's position in the
    object's frame, so a moved or rotated planet keeps its poles)."""
    mat = bpy.data.materials.get(MATERIAL_NAME)
    if mat is not None:
        return mat
    m = NodeMaterial(MATERIAL_NAME)
    height = m.attribute(mesh_build.HEIGHT_ATTRIBUTE, 200)
    steep = m.ramp(m.attribute(mesh_build.SLOPE_ATTRIBUTE, -100), *STEEP, -100)
    ground = m.mix(m.ramp(height, *HIGHLAND, 200), (*GRASS, 1.0), (*SEDIMENT, 1.0), 200)
    rocky = m.mix(steep, ground, (*ROCK, 1.0), 0, x=-350)
    position = m.object_position(-300, x=-1600)
    sin_latitude = m.math("ABSOLUTE", m.math("DIVIDE", m.separate_z(position, -250, x=-1400),
                                             m.vector_math("LENGTH", position, -400, x=-1400), -300, x=-1200),
                          0.0, -300, x=-1050)
    polar = m.math("MULTIPLY", m.math("MAXIMUM", m.math("SUBTRACT", sin_latitude, POLAR_FROM, -300, x=-900),
                                      0.0, -300, x=-800), POLAR_GAIN, -300, x=-700)
    snow = m.ramp(m.math("ADD", height, polar, -250, x=-600), *SNOW, -250, x=-450)
    m.base_color(m.mix(snow, rocky, SNOW_WHITE, -100, x=-200))
    return m.material
