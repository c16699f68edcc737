# SPDX-License-Identifier: GPL-3.0-or-later
"""The one reader of the library's parameter rows in Python (fracterra/params.h).

A row describes one field of a params struct. It reaches Python from the
loaded library (binding.py reads ft_param_info) or, when none loads, from the
snapshot `fracterra params --json` wrote beside the add-on (params.py). Both
become the same dict here, in the form `fracterra params --json` writes, and
every user (the ctypes layout in binding.py, the add-on's settings in
params.py, the Python package's keywords) reads the flags, bounds and enum
items through this module only:

    name, type ("double", "enum", ...), offset, size, count, flags, since,
    element_type, element_kind, default, hard_min/hard_max/soft_min/soft_max
    (None when unbounded), min_exclusive, max_exclusive, unit, label, doc,
    methods, items [{name, label, doc, value, cli}],
    settable (a caller sets it: not struct_size, not data), zero_is_auto.

Enum values are matched as the CLI matches them (cli/param_flags.cpp): the
item's name or label, case-insensitive, with "_" and " " read as "-"
("RUGGED_MOUNTAINS"... "Rugged Mountains", "rugged-mountains", "land").
"""

FT_PARAM = ("uint32", "int32", "int64", "uint64", "float", "double", "bool", "enum", "pointer", "string",
            "callback", "opaque")
FLAG_STRUCT_SIZE, FLAG_DATA, FLAG_MIN_EXCLUSIVE, FLAG_MAX_EXCLUSIVE, FLAG_ZERO_IS_AUTO = 1, 2, 4, 8, 16
_UNBOUNDED = 1.7e308  # the tables' +-DBL_MAX: no bound


def _text(b):
    return b.decode() if isinstance(b, bytes) else (b or "")


def cli_name(text):
    """The CLI's spelling of a name or label: lower case, "_" and " " as "-"."""
    return text.lower().replace("_", "-").replace(" ", "-")


def _bound(v):
    return None if v is None or abs(v) >= _UNBOUNDED else v


def _derived(row):
    flags = row["flags"]
    row["settable"] = not flags & (FLAG_STRUCT_SIZE | FLAG_DATA)
    row["min_exclusive"] = bool(flags & FLAG_MIN_EXCLUSIVE)
    row["max_exclusive"] = bool(flags & FLAG_MAX_EXCLUSIVE)
    row["zero_is_auto"] = bool(flags & FLAG_ZERO_IS_AUTO)
    for item in row["items"]:
        item.setdefault("cli", cli_name(item["name"]))
    return row


def row_from_info(info):
    """One ft_param_info (binding.ParamInfo) as a row."""
    row = {name: getattr(info, name) for name in ("name", "type", "offset", "size", "count", "flags", "since",
                                                    "element_kind", "methods")}
    row.update(name=_text(info.name), unit=_text(info.unit), label=_text(info.label), doc=_text(info.doc),
               type=FT_PARAM[info.type], element_type=FT_PARAM[info.element_type] if info.type == 8 else None,
               default=info.default_value, hard_min=_bound(info.hard_min), hard_max=_bound(info.hard_max),
               soft_min=_bound(info.soft_min), soft_max=_bound(info.soft_max),
               items=[{"name": _text(e.name), "label": _text(e.label), "doc": _text(e.doc), "value": e.value}
                      for e in info.enum_items[:info.enum_count]])
    return _derived(row)


def row_from_json(j):
    """One field of `fracterra params --json` as a row (it names no pointed-to struct: element_kind -1)."""
    row = {k: v for k, v in j.items() if k != "flag"}
    row.setdefault("element_kind", -1)
    row.setdefault("element_type", None)
    return _derived({**row, "items": [dict(i) for i in j.get("items") or ()]})


def enum_value(row, given):
    """The C value of enum row `row` that `given` names (a name or label, as the CLI reads it; an int is
    taken as the value itself). Raises ValueError naming the allowed names."""
    if isinstance(given, bool) or not isinstance(given, (str, int)):
        raise TypeError(f"{row['name']} is one of {allowed_text(row)}, got {given!r}")
    for item in row["items"]:
        if (isinstance(given, int) and given == item["value"]) or \
                (isinstance(given, str) and cli_name(given) in (item["cli"], cli_name(item["label"]))):
            return item["value"]
    raise ValueError(f"{row['name']} must be one of {allowed_text(row)}, got {given!r}")


def enum_item(row, value):
    """The item of enum row `row` with C value `value`."""
    return next(i for i in row["items"] if i["value"] == int(value))


def allowed_text(row):
    """"midpoint, fbm, ..." or "gentle-valleys (Gentle Valleys), ...": the names an enum takes."""
    return ", ".join(i["cli"] + (f" ({i['label']})" if i["label"] and cli_name(i["label"]) != i["cli"] else "")
                     for i in row["items"])


def default_text(row):
    """The default as a reader types it back."""
    if row["type"] == "enum":
        return enum_item(row, row["default"])["cli"]
    if row["type"] == "bool":
        return str(bool(row["default"]))
    if row["type"] in ("uint32", "int32", "int64", "uint64"):
        return "auto" if row["zero_is_auto"] and row["default"] == 0 else str(int(row["default"]))
    return f"{row['default']:g}"


def range_text(row):
    """"[0, 1]", "(0, inf) world units", "one of ...": what the library accepts."""
    if row["type"] == "enum":
        return "one of " + allowed_text(row)
    if row["type"] == "bool":
        return "True or False"
    lo, hi = row["hard_min"], row["hard_max"]
    left = "(" if row["min_exclusive"] or lo is None else "["
    right = ")" if row["max_exclusive"] or hi is None else "]"
    text = f"{left}{'-inf' if lo is None else f'{lo:g}'}, {'inf' if hi is None else f'{hi:g}'}{right}"
    return text + (f" {row['unit']}" if row["unit"] else "") + (" (0: auto)" if row["zero_is_auto"] else "")


__all__ = ["row_from_info", "row_from_json", "enum_value", "enum_item", "allowed_text", "default_text",
           "range_text", "cli_name", "FT_PARAM", "FLAG_STRUCT_SIZE", "FLAG_DATA", "FLAG_MIN_EXCLUSIVE",
           "FLAG_MAX_EXCLUSIVE", "FLAG_ZERO_IS_AUTO"]
