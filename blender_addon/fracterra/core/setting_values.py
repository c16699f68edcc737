# SPDX-License-Identifier: GPL-3.0-or-later
"""Settings as values: the defaults of a list of settings, whether one matters
for a method, the grid a terrain's settings describe, its Preview's settings, and
the copies between values, C structs and objects holding the settings. The lists
are params.py's tables (TERRAIN_OBJECT_PARAMS unless another is given)."""

from . import params


def defaults(param_list=None):
    """{name: default} for every setting a terrain object stores (unless another list is given)."""
    return {p.name: p.default for p in param_list or params._table("TERRAIN_OBJECT_PARAMS")}


def is_used(param, method):
    """True when `param` matters for `method` (used to lay out panels)."""
    return param.methods is None or method in param.methods


def grid_shape(values):
    """(nx, ny) of the terrain that settings `values` (a dict) describe."""
    if values["method"] in params._table("DYADIC_METHODS"):
        side = 2 ** values["levels"] + 1
        return side, side
    return values["width"], values["height"]


def preview_values(values):
    """The settings of the Preview of terrain `values`: Levels lowered to Preview
    Levels (never below a reference's own levels, which the preview must pass
    through too). The same settings when the method has no levels or the Final
    is no larger."""
    if values["method"] not in params._table("DYADIC_METHODS"):
        return values
    floor = values["reference_levels"] if values.get("reference_source") in ("IMAGE", "DEM") else 1
    levels = min(values["levels"], max(values.get("preview_levels", values["levels"]), floor))
    return {**values, "levels": levels} if levels != values["levels"] else values


def planet_preview_values(values):
    """The settings of a planet's Preview: its Level lowered to Preview Level
    (the same settings when the Final is no larger)."""
    level = min(values["level"], values["preview_level"])
    return {**values, "level": level} if level != values["level"] else values


def fill_struct(struct, values, param_list=None):
    """Copies the values that have a C field into a ctypes params struct
    (ft_terrain_params unless another list is given).

    `values` maps names to values; names it lacks keep the struct's value.
    """
    for p in param_list or params._table("TERRAIN_PARAMS"):
        if p.field and p.name in values:
            setattr(struct, p.field, p.c_value(values[p.name]))
    return struct


def values_of(obj, param_list=None):
    """{name: value} read from an object whose attributes are the settings
    (those a terrain object stores unless another list is given)."""
    return {p.name: (tuple(v) if p.kind == "vector" else v)
            for p in param_list or params._table("TERRAIN_OBJECT_PARAMS") for v in [getattr(obj, p.name)]}
