# SPDX-License-Identifier: GPL-3.0-or-later
"""The settings of the add-on, made from the library's own description of its
parameter structs (fracterra/params.h): names, defaults, ranges, enum items,
labels, tooltips and which methods use each field come from the library's
tables. What is the add-on's own is stated here, once: the defaults and
limits where Blender differs from the library (each with its reason) and the
settings that exist only in Blender (sea level, reference source, UVs...).

Each Param names its property (the C field's name, shared with the CLI), its
type, default, range and tooltip. The Blender side turns the list into
operator properties and into the PropertyGroup stored on terrain objects;
`fill_struct` copies the values into the C struct.

The description comes from the loaded library, or, when it cannot be loaded
(the add-on still registers and says what to do), from `params.json`, the
same tables written by `fracterra params --json` when the add-on zip was
built beside its library.

This file holds the Param and the reading of the library's rows into Params;
blender_overrides.py what Blender changes in them, addon_settings.py the
add-on's own settings and the tables of every operator and object (made on
first use, as params.TERRAIN_PARAMS ...), setting_values.py the helpers on
values (defaults, fill_struct, values_of, ...). Their names are reachable here
too (params.X), as before they moved.
"""

import json
from dataclasses import dataclass, field as dc_field
from pathlib import Path

from .binding import PARAMS_KINDS, library
from .rows import row_from_json
from .blender_overrides import (BLENDER_LIMITS, BLENDER_OVERRIDES, NOT_PROPERTIES, _BY_UNIT, _PRECISION,
                                display_scale_of, shown_name)  # noqa: F401 (params.shown_name)
from .errors import LibraryNotFoundError


# Settings whose change changes the vertex count (rebuild, not rewrite).
_GEOMETRY = {"method", "levels", "width", "height"}
SNAPSHOT = Path(__file__).resolve().parent / "params.json"


@dataclass(frozen=True)
class Param:
    name: str
    kind: str  # 'int', 'float', 'bool', 'enum', 'string'
    default: object
    label: str
    description: str
    min: float = None
    max: float = None
    soft_min: float = None
    soft_max: float = None
    items: tuple = ()
    field: str = None  # the ft_terrain_params field, None for add-on-only settings
    subtype: str = "NONE"  # Blender subtype: 'DISTANCE', 'ANGLE', 'FACTOR', ...
    unit: str = "NONE"  # Blender unit: 'LENGTH', 'ROTATION'
    step: int = None
    precision: int = None
    display_scale: float = None  # Blender shows value x this (a power of ten); None: as is
    unit_text: str = ""  # a unit Blender cannot show itself ("years", "1/yr"): drawn beside the label
    methods: frozenset = dc_field(default=None)  # methods that use it; None: all
    geometry: bool = False  # changing it changes the vertex count (rebuild, not rewrite)

    def c_value(self, value):
        """The value as the C struct stores it."""
        if self.kind == "enum":
            return next(item[3] for item in self.items if item[0] == value)
        if self.kind == "bool":
            return 1 if value else 0
        return value


def _description():
    """{kind name: [rows]} from the loaded library, else from the snapshot beside this file (rows.py reads both)."""
    try:
        lib = library()
    except LibraryNotFoundError:
        if not SNAPSHOT.is_file():
            raise
        tables = json.loads(SNAPSHOT.read_text())
        # "ft_terrain_params" -> "terrain"
        return {name[3:-7]: [row_from_json(f) for f in table["fields"]] for name, table in tables.items()}
    return lib.param_rows


_KIND_OF_TYPE = {"int32": "int", "int64": "int", "uint64": "int", "double": "float", "float": "float",
                 "bool": "bool", "enum": "enum"}


def _param_from_row(row, kind_name, method_items):
    """The add-on's Param for one library field, with Blender's limits and overrides applied."""
    name = row["name"]
    kind = _KIND_OF_TYPE[row["type"]]
    items = tuple((i["name"], i["label"], i["doc"], i["value"]) for i in row.get("items") or ())
    default = row["default"]
    if kind == "enum":
        default = next(ident for ident, _l, _d, value in items if value == int(default))
    elif kind == "bool":
        default = bool(default)
    elif kind == "int":
        default = int(default)
    default = BLENDER_OVERRIDES.get(kind_name, {}).get(name, (default,))[0]
    lo, hi = row["hard_min"], row["hard_max"]
    if lo is not None and row["min_exclusive"]:
        lo += 1e-6 if lo == 0 else abs(lo) * 1e-6  # Blender has no open bound; the library refuses lo itself
    if hi is not None and row.get("max_exclusive"):
        hi -= 1e-6 if hi == 0 else abs(hi) * 1e-6
    if name in BLENDER_LIMITS.get(kind_name, {}):
        lo, hi, _reason = BLENDER_LIMITS[kind_name][name]
    soft_lo, soft_hi = row["soft_min"], row["soft_max"]
    if kind == "int":  # IntProperty bounds are 32-bit integers
        def fit(v):
            return None if v is None else int(min(max(v, -2**31), 2**31 - 1))
        lo, hi, soft_lo, soft_hi = fit(lo), fit(hi), fit(soft_lo), fit(soft_hi)
    methods = None
    if row["methods"] != 2**64 - 1 and method_items:
        methods = frozenset(ident for ident, _l, _d, value in method_items if row["methods"] >> value & 1)
    look = _BY_UNIT.get(row["unit"], {})
    if kind == "float" and not look and lo == 0 and hi == 1:
        look = {"subtype": "FACTOR"}
    description = row["doc"] + (f" ({row['unit']})" if row["unit"] and not look else "")
    # Units Blender has no unit for are drawn with the label ("Step Length (years)");
    # a count's unit is its label already ("River Steps" in steps).
    unit_text = row["unit"] if row["unit"] and not look and row["unit"] not in row["label"].lower() else ""
    numeric = kind in ("int", "float")
    return Param(name, kind, default, row["label"], description,
                 min=lo if numeric else None, max=hi if numeric else None,
                 soft_min=soft_lo if numeric else None, soft_max=soft_hi if numeric else None,
                 items=items, field=name, subtype=look.get("subtype", "NONE"), unit=look.get("unit", "NONE"),
                 precision=_PRECISION.get(name), display_scale=display_scale_of(row), unit_text=unit_text,
                 methods=methods,
                 geometry=name in _GEOMETRY)


def _check_names(kind_name, rows):
    """Every field an override table names is a field of the library's struct: a
    misspelt or removed name would otherwise change nothing, silently."""
    fields = {r["name"] for r in rows}
    for table_name, table in (("BLENDER_OVERRIDES", BLENDER_OVERRIDES), ("BLENDER_LIMITS", BLENDER_LIMITS),
                              ("NOT_PROPERTIES", NOT_PROPERTIES)):
        unknown = set(table.get(kind_name, {})) - fields
        if unknown:
            raise KeyError(f"{table_name}[{kind_name!r}] names {sorted(unknown)}, not fields of "
                           f"ft_{kind_name}_params")


def library_params(kind_name):
    """The add-on's Params for every setting of the library's struct `kind_name` ("terrain")."""
    if kind_name not in PARAMS_KINDS:
        raise KeyError(f"{kind_name!r} is not a params struct of the library ({', '.join(PARAMS_KINDS)})")
    rows = _description()[kind_name]
    _check_names(kind_name, rows)
    method = next((r for r in rows if r["name"] == "method"), None)
    method_items = tuple((i["name"], i["label"], i["doc"], i["value"]) for i in method["items"]) if method else ()
    skip = NOT_PROPERTIES.get(kind_name, {})
    return tuple(_param_from_row(r, kind_name, method_items) for r in rows
                 if r["type"] in _KIND_OF_TYPE and r["settable"] and r["count"] == 1 and r["name"] not in skip)


_LAZY = ("DYADIC_METHODS", "TERRAIN_PARAMS", "EROSION_PARAMS", "ERODE_PARAMS", "RIVERS_PARAMS", "TERRAIN_OBJECT_PARAMS",
         "PARAMS_BY_NAME", "POLYLINE_PARAMS", "FRACTALIZE_PARAMS", "PLANET_PARAMS", "PLANET_OBJECT_PARAMS")


# What moved out of this file and is still reached as params.X (PEP 562: imported
# on first use, so that those files may import this one).
_ELSEWHERE = {
    "addon_settings": ("REFERENCE_SOURCES", "FALLOFF_MASK_SOURCES", "MAP_SOURCES", "EROSION_MAP_PARAMS", "RIVERS",
                       "RIVERS_PREFIX", "BASE_SOURCES"),
    "setting_values": ("defaults", "is_used", "grid_shape", "preview_values", "planet_preview_values",
                       "fill_struct", "values_of"),
}


def __getattr__(name):
    """params.TERRAIN_PARAMS and the other tables, made on first use, and the names of
    addon_settings.py and setting_values.py (PEP 562)."""
    import importlib
    if name in _LAZY:
        globals().update(importlib.import_module(".addon_settings", __package__)._tables())
        return globals()[name]
    for module, names in _ELSEWHERE.items():
        if name in names:
            return getattr(importlib.import_module("." + module, __package__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _table(name):
    return globals()[name] if name in globals() else __getattr__(name)
