# SPDX-License-Identifier: GPL-3.0-or-later
"""From polyline settings to curve (or point-cloud) data, for a new object or
an existing one regenerated in place from the settings stored on it, as
progress.Jobs: the library generates in the worker thread, the curve is
built in steps in the main thread (status-bar progress, Esc cancels)."""

import json

import bpy

from ... import core
from ...core import params
from .curve import LineArrays, fill_curve_steps, new_curve, point_cloud_from_arrays
from ..common.preferences import library_threads
from ..common.jobs import Job, run_job
from ..common.reporting import SettingsError


def default_radius(base):
    """The tube radius that keeps a new line visible at any size: 1/200 of its
    chord (a 10 m bolt: 5 cm)."""
    (x0, y0, z0), (x1, y1, z1) = base[0], base[-1]
    chord = ((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2) ** 0.5
    return max(chord, 1e-3) / 200


def used_values(values):
    """Only the settings the method uses: the library refuses e.g. branching for a
    Koch curve, and the settings stored on an object keep every field."""
    return {p.name: values[p.name] for p in params.POLYLINE_PARAMS if params.is_used(p, values["method"])}


def generate_lines(values, base, threads, progress=None):
    """LineArrays of the polyline of `values` along `base` (bpy-free: a job's worker)."""
    with core.generate_polylines(used_values(values), base=base, progress=progress, threads=threads) as pl:
        return LineArrays(pl)


def build_data(values, lines):
    """Build steps of the curve (or, for IFS, the mesh of points) of `lines`;
    returns (data, summary). Nothing is left if it is cancelled."""
    summary = f"{lines.line_count} line(s), {lines.vertex_count} vertices"
    if values["method"] == "IFS":
        return point_cloud_from_arrays("Fractal Points", lines.xyz), summary
    curve = new_curve("Fractal Polyline", values["bevel"])
    try:
        yield from fill_curve_steps(curve, lines)
    except BaseException:  # GeneratorExit too: a cancel leaves no curve behind
        bpy.data.curves.remove(curve)
        raise
    return curve, summary
    yield  # noqa: unreachable - a generator even for IFS


def polyline_job(values, base, context, label="Generating polyline"):
    """A progress.Job whose value is (data, summary): a new curve, or a mesh of
    points for IFS, for `values` along `base`. Nothing is left if it is cancelled."""
    threads = library_threads(context)
    return Job(label, lambda progress: generate_lines(values, base, threads, progress),
               lambda lines: build_data(values, lines))


def swap_data(obj, data):
    """Gives polyline object `obj` its new curve or point mesh `data`, with the old
    one's materials; the old one goes when nothing else uses it."""
    old = obj.data
    for mat in old.materials:
        data.materials.append(mat)
    obj.data = data
    if old.users == 0:
        (bpy.data.meshes if isinstance(old, bpy.types.Mesh) else bpy.data.curves).remove(old)


def polyline_data(values, base, context):
    """(data, summary), built here and now (scripts)."""
    return run_job(polyline_job(values, base, context))


def stored_base(settings):
    """The base nodes a polyline object regenerates along, in its own frame:
    Start and End, or the nodes of the object it was made from (kept as JSON)."""
    if settings.base_source == "ACTIVE" and settings.base_nodes:
        return [tuple(p) for p in json.loads(settings.base_nodes)]
    if tuple(settings.start) == tuple(settings.end):
        raise SettingsError("Start and End are the same point; move one of them")
    return [tuple(settings.start), tuple(settings.end)]


def regenerate_job(obj, context):
    """A progress.Job that rebuilds a fractal polyline object's data from its stored
    settings; the object (name, transform, parent, modifiers, materials) stays.
    Its value is a summary."""
    settings = obj.fracterra_polyline
    values = params.values_of(settings, params.POLYLINE_PARAMS)
    wants = "MESH" if values["method"] == "IFS" else "CURVE"
    if obj.type != wants:
        raise SettingsError("IFS points are a mesh and the other methods a curve: switching between them "
                            "changes the object type; add a new Fractal Polyline instead")
    job = polyline_job(values, stored_base(settings), context, "Regenerating polyline")
    make = job.build

    def build(lines):
        data, summary = yield from make(lines)
        swap_data(obj, data)
        return summary

    return Job(job.label, job.work, build)


def regenerate_polyline(obj, context):
    """Rebuilds a fractal polyline object here and now (auto-update, scripts); returns a summary."""
    return run_job(regenerate_job(obj, context))
