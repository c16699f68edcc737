# SPDX-License-Identifier: GPL-3.0-or-later
"""The library's parameter tables (fracterra/params.h) against what is built
from them: the ctypes Structures, the defaults that ft_*_params_init writes,
and the add-on's parameter list (core/params.py). The library is the
definition: everything else must agree with it or state why it differs."""

import ctypes
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from fracterra.core import binding

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def lib(core):
    return core.library()


def test_every_kind_is_described_and_laid_out_as_the_library_says(lib):
    count = ctypes.c_int32()
    for kind_name, kind in binding.PARAMS_KINDS.items():
        name, size, rows = lib.describe(kind)
        assert name == f"ft_{kind_name}_params"
        assert rows[0]["name"] == "struct_size" and rows[0]["flags"] & binding.FLAG_STRUCT_SIZE
        offsets = [r["offset"] for r in rows]
        assert offsets == sorted(offsets) and len(set(offsets)) == len(offsets)
        assert rows[-1]["offset"] + rows[-1]["size"] <= size
        struct = lib.struct_types[kind]
        assert ctypes.sizeof(struct) == size
    assert lib.ft_params_describe(max(binding.PARAMS_KINDS.values()) + 1, None, None, ctypes.byref(count)) != 0
    assert "kind" in lib.ft_last_error().decode()


def test_init_writes_the_tables_defaults(lib):
    for kind_name, kind in binding.PARAMS_KINDS.items():
        p = lib.struct_types[kind]()
        status = getattr(lib, f"ft_{kind_name}_params_init")(ctypes.byref(p))
        if status is not None:  # ft_dem_refine_params_init returns nothing
            lib.check(status)
        for row in lib.param_rows[kind_name]:
            if row["type"] in ("pointer", "callback", "string"):
                continue
            value = getattr(p, row["name"])
            values = list(value) if row["count"] > 1 else [value]
            for v in values:
                assert v == pytest.approx(row["default"], rel=1e-7), row["name"]


def test_a_value_outside_a_hard_range_is_refused_with_the_range(core, lib):
    for row in lib.param_rows["terrain"]:
        if row["type"] != "double" or row["hard_max"] is None or row["methods"] != 2**64 - 1:
            continue
        with pytest.raises(core.InvalidArgumentError, match=row["name"]):
            core.generate_terrain(levels=3, **{row["name"]: row["hard_max"] * 2 + 1})


def _addon_params(core, kind_name):
    lists = {"terrain": core.params.TERRAIN_PARAMS, "polyline": core.params.POLYLINE_PARAMS,
             "fractalize": core.params.FRACTALIZE_PARAMS, "erosion": core.params.EROSION_PARAMS}
    return {p.field: p for p in lists.get(kind_name, ()) if p.field}


def test_addon_defaults_are_the_librarys_or_a_stated_override(core, lib):
    for kind_name in binding.PARAMS_KINDS:
        addon = _addon_params(core, kind_name)
        overrides = core.params.BLENDER_OVERRIDES.get(kind_name, {})
        for row in lib.param_rows[kind_name]:
            p = addon.get(row["name"])
            if p is None:
                continue
            if row["name"] in overrides:
                default, reason = overrides[row["name"]]
                assert p.default == default and len(reason) > 20, row["name"]
            elif row["type"] == "enum":
                assert p.c_value(p.default) == row["default"], row["name"]
            else:
                assert p.default == pytest.approx(row["default"]), row["name"]


def test_addon_enums_are_the_librarys(core, lib):
    for kind_name in binding.PARAMS_KINDS:
        addon = _addon_params(core, kind_name)
        for row in lib.param_rows[kind_name]:
            if row["type"] == "enum" and row["name"] in addon:
                ours = [(ident, value) for ident, _l, _t, value in addon[row["name"]].items]
                assert ours == [(i["name"], i["value"]) for i in row["items"]], row["name"]


def test_addon_ranges_lie_within_the_librarys(core, lib):
    """Blender may narrow a hard range (a mesh it can hold), never widen it."""
    for kind_name in binding.PARAMS_KINDS:
        addon = _addon_params(core, kind_name)
        for row in lib.param_rows[kind_name]:
            p = addon.get(row["name"])
            if p is None or row["type"] in ("enum", "bool", "uint64"):
                continue
            if p.min is not None and row["hard_min"] is not None:
                assert p.min >= row["hard_min"], row["name"]
            if p.max is not None and row["hard_max"] is not None:
                assert p.max <= row["hard_max"], row["name"]


def _cli():
    import os
    from pathlib import Path
    path = os.environ.get("FRACTERRA_CLI") or str(Path(__file__).resolve().parents[2] / "build/native/fracterra")
    if not Path(path).is_file():
        pytest.skip("the fracterra CLI is not built (ctest sets FRACTERRA_CLI)")
    return path


def _run(*args):
    import subprocess
    return subprocess.run([_cli(), *args], check=True, capture_output=True, text=True).stdout


def test_cli_params_json_is_the_librarys_table(lib):
    import json
    tables = json.loads(_run("params", "--json"))
    for kind_name, kind in binding.PARAMS_KINDS.items():
        name, size, rows = lib.describe(kind)
        cli = tables[name]
        assert cli["kind"] == kind and cli["size"] == size
        assert [f["name"] for f in cli["fields"]] == [r["name"] for r in rows]
        for f, r in zip(cli["fields"], rows):
            for key in ("offset", "size", "default", "hard_min", "hard_max", "soft_min", "soft_max"):
                want, got = r[key], f[key]
                assert (got is None and want is None) or got == pytest.approx(want), (r["name"], key)
            assert [i["value"] for i in f.get("items", [])] == [i["value"] for i in r["items"]]
            # The snapshot reads as the library's rows (but which struct a pointer points to).
            snap = binding.rows.row_from_json(f)
            assert {k: v for k, v in snap.items() if not k.startswith("element_")} == \
                {k: v for k, v in r.items() if not k.startswith("element_")}, r["name"]


# Which command offers each described struct's settings as flags, and the
# fields it offers in a form of its own instead (field -> that flag).
CLI_COMMANDS = {
    "terrain": ("terrain", {"width": "--size", "height": "--size", "center_x": "--center", "center_y": "--center"}),
    "profile": ("profile", {}),
    "polyline": ("polyline", {}),
    "fractalize": ("fractalize", {}),
    "pov_scene": ("scene", {"world_size_x": "--size", "world_size_y": "--size", "vertical_scale": "--vertical-scale",
                            "has_sea": "--water", "sea_level": "--water"}),
    "pov_sweep": ("scene", {"default_radius": "--radius", "radius_scale": "--radius-scale"}),
    "hurst": ("analyze", {"method": "--method", "transects": "--method"}),
    "clouds": ("clouds", {"threshold": "--threshold", "threshold_is_quantile": "--threshold"}),
    "dem_refine": ("refine", {"levels_added": "--levels", "hurst": "--hurst", "sigma": "--sigma",
                              "window_x": "--window", "window_y": "--window", "window_side": "--window"}),
    "erosion": ("erode", {}),
    "hydrology": ("rivers", {}),
    "planet": ("planet", {}),
    # The pipeline's settings go with the terrain's; the terrain's --threads serves every stage.
    "build": ("terrain", {"threads": "--threads"}),
    # A splat rule set is a list of layers: their fields are a rules file's, not flags.
    "splat": ("splat", dict.fromkeys(("height_min", "height_max", "height_blend", "slope_min", "slope_max",
                                      "slope_blend", "deposit_min", "deposit_blend", "flow_min", "flow_blend",
                                      "weight"), "--rules")),
}
# Flags users relied on before the flags came from the tables: each still works (an alias).
CLI_ALIASES = {
    "polyline": {"ifs_preset": "--ifs", "ifs_points": "--points"},
    "pov_scene": {"camera_azimuth_deg": "--azimuth", "camera_elevation_deg": "--elevation",
                  "camera_fov_deg": "--fov", "camera_distance_scale": "--zoom-out",
                  "sun_azimuth_deg": "--sun-azimuth", "sun_elevation_deg": "--sun-elevation"},
    "clouds": {"bit_depth": "--bits"},
    # issue 15's short names: `erode --fluvial 60 --hydraulic 100 --thermal 20 --talus 33`
    "erosion": {"fluvial_steps": "--fluvial", "hydraulic_iterations": "--hydraulic",
                "thermal_iterations": "--thermal", "talus_degrees": "--talus"},
    "build": {"erosion_preset": "--erode"},  # `terrain --erode valleys` (issue 15)
}


@pytest.mark.parametrize("kind_name", sorted(CLI_COMMANDS))
def test_cli_help_has_every_setting_with_the_librarys_default(lib, kind_name):
    import re
    command, own_form = CLI_COMMANDS[kind_name]
    text = _run(command, "--help")
    aliases = CLI_ALIASES.get(kind_name, {})
    checked = 0
    for row in lib.param_rows[kind_name]:
        if (not row["settable"] or row["count"] != 1
                or row["type"] in ("pointer", "callback", "string")):
            continue
        flag = "--" + row["name"].replace("_", "-")
        if row["name"] in own_form:
            assert own_form[row["name"]] in text, (command, own_form[row["name"]])
            if own_form[row["name"]] != flag:  # e.g. --sigma: the own form keeps the field's name
                assert not re.search(re.escape(flag) + r"[ ,\n]", text), (command, flag, "offered twice")
            continue
        # CLI11 lists "--name,--alias TYPE=default" (or "--name TYPE=default").
        names = re.escape(flag) + (r"," + re.escape(aliases[row["name"]]) if row["name"] in aliases else "")
        m = re.search(names + r"(?: (\S+))?\s", text)
        assert m, (command, flag)
        checked += 1
        if row["type"] == "bool":
            continue
        default = m.group(1).rsplit("=", 1)[1]
        if row["type"] == "enum":
            assert default == binding.rows.enum_item(row, row["default"])["cli"], flag
        elif row["zero_is_auto"] and row["default"] == 0:
            assert default == "auto", flag  # the sentinel the row documents
        else:
            assert float(default) == pytest.approx(row["default"]), flag
    assert checked >= 1 or kind_name == "splat", command  # splat: every field is a rules file's


def test_every_described_struct_has_a_command():
    """A new params struct gets its flags somewhere (or this list says where it is not offered)."""
    assert set(CLI_COMMANDS) == set(binding.PARAMS_KINDS)


def test_cli_refuses_a_table_flag_out_of_range_with_the_librarys_words():
    """The CLI's table flags are checked by the library, with its message."""
    import subprocess
    run = subprocess.run([_cli(), "polyline", "--method", "fpl", "--branch-prob", "1.5", "--stats"],
                         capture_output=True, text=True)
    assert run.returncode != 0 and "branch_prob must be in [0, 1], got 1.5" in run.stderr, run.stderr


def test_soversion_follows_the_abi_major(lib):
    import re
    import shutil
    import subprocess
    if not shutil.which("readelf"):
        pytest.skip("readelf (binutils) is not installed")
    dynamic = subprocess.run(["readelf", "-d", str(lib.path)], check=True, capture_output=True, text=True).stdout
    soname = re.search(r"Library soname: \[(.*?)\]", dynamic).group(1)
    assert soname == f"libfracterra.so.{lib.abi_major}"
    assert lib.abi_major == binding.ABI_MAJOR == 2


def test_importing_the_settings_loads_no_library():
    """core.params builds its tables on first use: importing core (a script, a Dask
    worker, the add-on before its preferences name a library) loads nothing."""
    code = ("import sys; sys.path.insert(0, %r)\n"
            "import fracterra.core as core\n"
            "from fracterra.core import binding\n"
            "assert binding._library is None, 'loaded on import'\n"
            "assert len(core.params.TERRAIN_PARAMS) > 10\n"
            "assert binding._library is not None, 'not loaded on first use'\n") % str(ROOT / "blender_addon")
    subprocess.run([sys.executable, "-c", code], check=True, env=os.environ.copy())


def test_terrain_erosion_and_rivers_settings_are_separate_tables(core):
    p = core.params
    terrain, erode = {q.name for q in p.TERRAIN_PARAMS}, {q.name for q in p.ERODE_PARAMS}
    rivers = {q.name for q in p.RIVERS_PARAMS}
    assert not terrain & erode and not (terrain | erode) & rivers
    assert "erode_preset" in erode and "fluvial_steps" in erode and "levels" in terrain
    # Every erosion setting has its ft_erosion_params field: nothing is stored without one.
    assert all(q.field == q.name for q in p.EROSION_PARAMS)
    # Rivers and Lakes: the switch, then ft_hydrology_params' fields under "rivers_" (seed,
    # smoothing and tolerance are the terrain's names too); the sea is the terrain's.
    assert p.RIVERS_PARAMS[0].name == "rivers" and p.RIVERS_PARAMS[0].field is None
    assert all(q.name == "rivers_" + q.field for q in p.RIVERS_PARAMS[1:])
    assert {"rivers_min_area", "rivers_width_coefficient"} <= rivers and "rivers_sea" not in rivers
    assert [q.name for q in p.TERRAIN_OBJECT_PARAMS] == [q.name for q in p.TERRAIN_PARAMS + p.ERODE_PARAMS
                                                          + p.RIVERS_PARAMS]


def test_an_override_of_a_field_the_library_lacks_is_refused(core, monkeypatch):
    monkeypatch.setitem(core.params.BLENDER_OVERRIDES, "terrain",
                        {**core.params.BLENDER_OVERRIDES["terrain"], "levls": (9, "a misspelt name")})
    with pytest.raises(KeyError, match="levls"):
        core.params.library_params("terrain")
