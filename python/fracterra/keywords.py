# SPDX-License-Identifier: GPL-3.0-or-later
"""Keyword arguments from the library's parameter tables: each function's
settings are the fields of its params struct (names, defaults, ranges, units
and docs as `fracterra params` lists them), read through core/rows.py, the
one reader of the rows. A value is checked by the library; what Python must
decide itself (an unknown name, an enum's spelling, a wrong type) is refused
here with what is allowed."""

from __future__ import annotations

import difflib
import inspect
import numbers
from typing import Optional

import numpy as np

from .core import rows as rows_mod
from .core.binding import library
from .core.errors import InvalidArgumentError

_PY_TYPES = {"uint32": int, "int32": int, "int64": int, "uint64": int, "float": float, "double": float,
             "bool": bool, "enum": str}


class Table:
    """The settable fields of params struct `kind` ("terrain", "erosion", ...) but `skip`."""

    def __init__(self, kind: str, skip=()):
        self.kind = kind
        self.rows = {r["name"]: r for r in library().param_rows[kind]
                     if r["settable"] and r["type"] in _PY_TYPES and r["name"] not in skip}

    def __contains__(self, name):
        return name in self.rows

    def fill(self, struct, values: dict) -> None:
        """Sets struct's fields from {name: value}; every name must be one of the table's."""
        for name, value in values.items():
            row = self.rows.get(name)
            if row is None:
                raise unknown(name, self.rows)
            try:
                value = _c_value(row, value)
                if row["count"] > 1:
                    value = list(value)
                    if len(value) != row["count"]:
                        raise ValueError(f"{name} takes {row['count']} values, got {len(value)}")
                    getattr(struct, name)[:] = value
                else:
                    setattr(struct, name, value)
            except ValueError as e:
                raise InvalidArgumentError(str(e)) from None
            except TypeError as e:
                raise TypeError(f"{name} takes {_kind_text(row)}, got {value!r} ({e})") from None

    def parameters(self) -> list:
        """inspect.Parameters: keyword-only, default None (= the library's)."""
        return [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=None,
                                  annotation=Optional[_PY_TYPES[row["type"]]]) for name, row in self.rows.items()]

    def doc_lines(self) -> list:
        """One line per setting: label, doc, default, range and unit."""
        return [f"    {name}: {row['label']}. {row['doc']}. Default {rows_mod.default_text(row)}, "
                f"range {rows_mod.range_text(row)}." for name, row in self.rows.items()]


def _kind_text(row):
    t = row["type"]
    if t == "enum":
        return "one of " + rows_mod.allowed_text(row)
    if t == "bool":
        return "True or False"
    kind = "an integer" if _PY_TYPES[t] is int else "a number"
    return kind if row["count"] == 1 else f"{row['count']} of {kind[kind.index(' ') + 1:]}s"


def _c_value(row, value):
    t = row["type"]
    if t == "enum":
        return rows_mod.enum_value(row, value)
    if t == "bool":
        if not (isinstance(value, (bool, np.bool_)) or (isinstance(value, numbers.Integral) and value in (0, 1))):
            raise TypeError("not a bool")
        return 1 if value else 0
    if row["zero_is_auto"] and isinstance(value, str) and value.lower() == "auto":
        return 0
    if isinstance(value, (str, bytes)) or isinstance(value, bool):
        raise TypeError(f"{type(value).__name__} is not a number")
    if _PY_TYPES[t] is int and row["count"] == 1:
        if isinstance(value, float) and not value.is_integer():
            raise TypeError("not an integer")
        return int(value)
    return value


def unknown(name, allowed) -> TypeError:
    """The TypeError for an unknown keyword: the closest names, then all of them."""
    close = difflib.get_close_matches(name, list(allowed), n=3)
    hint = f" (did you mean {', '.join(close)}?)" if close else ""
    return TypeError(f"unknown setting {name!r}{hint}; the settings are: {', '.join(allowed)}")


def split(values: dict, tables: dict, own=()) -> dict:
    """{table name: {setting: value}} for `values` (None values dropped: the library's default), each
    name in the first table that has it; an unknown name raises TypeError listing them all."""
    out = {key: {} for key in tables}
    for name, value in values.items():
        if value is None:
            continue
        for key, table in tables.items():
            if name in table:
                out[key][name] = value
                break
        else:
            raise unknown(name, [n for t in tables.values() for n in t.rows] + list(own))
    return out


def document(fn, leading: list, tables: list, note: str = "") -> None:
    """Gives `fn` its signature (its leading parameters, then every table's
    settings as keyword-only arguments) and a docstring listing them."""
    params, seen = list(leading), {p.name for p in leading}
    lines = [inspect.getdoc(fn) or ""]
    for title, table in tables:
        lines += ["", f"{title} (the library's ft_{table.kind}_params; None keeps its default):"]
        for p, line in zip(table.parameters(), table.doc_lines()):
            if p.name in seen:
                continue
            seen.add(p.name)
            params.append(p)
            lines.append(line)
    if note:
        lines += ["", note]
    has_var_kw = any(p.kind is inspect.Parameter.VAR_KEYWORD for p in params)
    params = [p for p in params if p.kind is not inspect.Parameter.VAR_KEYWORD]
    if has_var_kw:
        params.append(inspect.Parameter("settings", inspect.Parameter.VAR_KEYWORD))
    fn.__signature__ = inspect.Signature(params, return_annotation=inspect.signature(fn).return_annotation)
    fn.__doc__ = "\n".join(lines)


__all__ = ["Table", "split", "document", "unknown"]
