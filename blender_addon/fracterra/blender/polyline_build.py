"""From polyline settings to curve (or point-cloud) data, for a new object or
an existing one regenerated in place from the settings stored on it."""

import json

import bpy

from .. import core
from ..core import params
from .curve_build import curve_from_polylines, point_cloud_from_polylines
from .prefs import library_threads
from .reporting import SettingsError, WindowProgress


def default_radius(base):
    """The tube radius that keeps a new line visible at any size: 1/200 of its
    chord (a 10 m bolt: 5 cm)."""
    (x0, y0, z0), (x1, y1, z1) = base[0], base[-1]
    chord = ((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2) ** 0.5
    return max(chord, 1e-3) / 200


def polyline_data(values, base, context):
    """(data, summary): a new curve, or a mesh of points for IFS, for `values` along `base`."""
    # Only what the method uses: the library refuses e.g. branching for a Koch curve,
    # and the settings stored on an object keep every field.
    values = {p.name: values[p.name] for p in params.POLYLINE_PARAMS if params.is_used(p, values["method"])}
    with WindowProgress(context) as progress, \
            core.generate_polylines(values, base=base, progress=progress, threads=library_threads(context)) as pl:
        if values["method"] == "IFS":
            data = point_cloud_from_polylines("Fractal Points", pl)
        else:
            data = curve_from_polylines("Fractal Polyline", pl, values["bevel"])
        return data, f"{pl.line_count} line(s), {pl.vertex_count} vertices"


def stored_base(settings):
    """The base nodes a polyline object regenerates along, in its own frame:
    Start and End, or the nodes of the object it was made from (kept as JSON)."""
    if settings.base_source == "ACTIVE" and settings.base_nodes:
        return [tuple(p) for p in json.loads(settings.base_nodes)]
    if tuple(settings.start) == tuple(settings.end):
        raise SettingsError("Start and End are the same point; move one of them")
    return [tuple(settings.start), tuple(settings.end)]


def regenerate_polyline(obj, context):
    """Rebuilds a fractal polyline object's data from its stored settings; the
    object (name, transform, parent, modifiers, materials) stays. Returns a summary."""
    settings = obj.fracterra_polyline
    values = params.values_of(settings, params.POLYLINE_PARAMS)
    wants = "MESH" if values["method"] == "IFS" else "CURVE"
    if obj.type != wants:
        raise SettingsError("IFS points are a mesh and the other methods a curve: switching between them "
                            "changes the object type; add a new Fractal Polyline instead")
    data, summary = polyline_data(values, stored_base(settings), context)
    old = obj.data
    for mat in old.materials:
        data.materials.append(mat)
    obj.data = data
    if old.users == 0:
        (bpy.data.meshes if wants == "MESH" else bpy.data.curves).remove(old)
    return summary
