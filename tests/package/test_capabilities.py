# SPDX-License-Identifier: GPL-3.0-or-later
"""One function per capability of the C ABI, from numpy to numpy, each
against the CLI on the same settings where the CLI writes a file (the same
bits), with keywords and help() from the library's tables and the library's
messages as FracterraError subclasses. Small sizes: seconds in all."""

import csv
import inspect
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import fracterra as ft

CLI = os.environ.get("FRACTERRA_CLI")
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def cli(*args):
    if not CLI:
        pytest.skip("FRACTERRA_CLI is not set (ctest sets it to the built fracterra)")
    run = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run


def test_every_capability_is_a_function():
    for name in ("terrain", "window", "erode", "rivers", "analyze", "polyline", "fpl_study", "coastline", "clouds",
                 "planet", "pov_scene", "render", "fractalize", "tiles", "splat", "save", "load"):
        assert callable(getattr(ft, name)), name
        assert getattr(ft, name).__doc__, name


def test_polyline_is_the_clis(tmp_path):
    lines = ft.polyline("fpl3d", depth=7, spread=0.3, seed=4, branch_prob=0.5)
    cli("polyline", "--method", "fpl3d", "--depth", 7, "--spread", 0.3, "--seed", 4, "--branch-prob", 0.5,
        "--out", tmp_path / "l.json")
    doc = json.loads((tmp_path / "l.json").read_text())
    got = doc["polylines"]
    assert len(got) == lines.line_count > 1  # the main line and its branches
    for k, line in enumerate(lines.lines()):
        assert np.array_equal(np.array(got[k]["points"], dtype=np.float64), line), k
    assert lines.main.shape == (2 ** 7 + 1, 3) and len(lines.branches) == lines.line_count - 1
    assert lines.radii.shape == (len(lines.xyz),) and lines.radii[0] > 0
    m = ft.analyze(lines)
    assert 1 < m["gamma"] and 0 < m["eta"] < 1 and m["mass_dimension"] > 1
    with pytest.raises(ft.InvalidArgumentError, match="method must be one of fpl"):
        ft.polyline("spiral")
    assert "branch_prob" in inspect.signature(ft.polyline).parameters
    assert "spread: " in ft.polyline.__doc__


def test_fpl_study_is_the_clis(tmp_path):
    study = ft.fpl_study(spreads=[0.1, 0.3], depths=[6, 8], count=20, seed=3)
    cli("study", "fpl", "--spread", "0.1,0.3", "--depth", "6,8", "--count", 20, "--seed", 3,
        "--out-csv", tmp_path / "s.csv")
    rows = list(csv.DictReader((tmp_path / "s.csv").open()))
    assert len(rows) == len(study["spread"]) == 4
    for i, row in enumerate(rows):
        assert float(row["spread"]) == study["spread"][i] and int(row["depth"]) == study["depth"][i]
        for ours, theirs in (("eta_mean", "eta_mean"), ("chi_mean", "chi_mean"), ("gamma_mean", "gamma_mean"),
                             ("mass_dimension_mean", "mass_dim_mean"), ("paper_gamma", "paper_gamma")):
            assert f"{study[ours][i]:.6g}" == row[theirs], (ours, i)
    with pytest.raises(ft.InvalidArgumentError, match="count"):
        ft.fpl_study(count=1)


def test_analyze_gives_the_fitted_points_and_horton():
    z = ft.terrain(method="midpoint", levels=7, seed=5, erode="land")
    a = ft.analyze(z, "spectral", points=True, rivers=True)
    assert a["estimator"] == "spectral" and len(a["fit"]["x"]) == a["points"]
    # The transects' periodogram falls as f^-(2H + 1): the points are the ones H was fitted on.
    slope = np.polyfit(np.log(a["fit"]["x"]), np.log(a["fit"]["y"]), 1)[0]
    assert slope == pytest.approx(-(2 * a["hurst"] + 1), abs=1e-6)
    r = a["rivers"]
    assert r["horton_orders"] >= 2 and r["bifurcation_ratio"] > 1 and r["drainage_density"] > 0
    assert len(r["streams"]) == r["horton_orders"] and r["streams"][0] >= r["streams"][-1]


def test_rivers_measures_are_the_clis(tmp_path):
    z = ft.terrain(method="midpoint", levels=7, seed=5, erode="land", world_size=10)
    ft.save(z, tmp_path / "z.npy")
    stats = json.loads(cli("rivers", "--in", tmp_path / "z.npy", "--stats").stdout)
    m = ft.rivers(z).measures()
    assert m["segments"] == stats["segments"] and m["total_length"] == pytest.approx(stats["total_length"])


def test_coastline_is_the_clis(tmp_path):
    z = ft.terrain(method="midpoint", levels=6, seed=9, world_size=20)
    ft.save(z, tmp_path / "z.npy")
    cli("coastline", "--in", tmp_path / "z.npy", "--level", "q0.4", "--world", "--out", tmp_path / "c.json")
    lines = ft.coastline(z, 0.4, quantile=True, world=True)
    got = json.loads((tmp_path / "c.json").read_text())["polylines"]
    assert len(got) == lines.line_count
    for k, line in enumerate(lines.lines()):
        assert np.allclose(np.array(got[k]["points"]), line, rtol=0, atol=1e-9), k
    with pytest.raises(ft.InvalidArgumentError, match="records no world size"):
        ft.coastline(np.asarray(z), 0.4, quantile=True, world=True)


def test_clouds_are_the_clis(tmp_path):
    from PIL import Image
    z = ft.terrain(method="midpoint", levels=6, seed=2)
    ft.save(z, tmp_path / "z.npy")
    cli("clouds", "--in", tmp_path / "z.npy", "--out", tmp_path / "c.png")
    assert np.array_equal(ft.clouds(z), np.asarray(Image.open(tmp_path / "c.png")).astype(np.uint16))
    assert ft.clouds(z, bit_depth=16).max() > 255


def test_planet_patches_are_the_clis(tmp_path):
    face = ft.planet("face", level=5, face=2, seed=3)
    patch = ft.planet("face", level=5, face=2, window=(8, 4, 9, 7), seed=3)
    assert np.array_equal(patch, face[4:11, 8:17])  # a patch is those samples of the face
    cli("planet", "--patch", "2,0,0,33,33", "--level", 5, "--seed", 3, "--out", tmp_path / "f.npy")
    assert np.array_equal(face, np.load(tmp_path / "f.npy"))
    eq = ft.planet("equirect", width=64, height=32, seed=3)
    assert eq.shape == (32, 64)
    mesh = ft.planet("mesh", level=3, seed=3)
    assert mesh["xyz"].shape == (6 * 4 ** 3 + 2, 3) and mesh["quads"].shape == (6 * 4 ** 3, 4)
    ico = ft.planet("icosphere", level=2, seed=3)
    assert ico["triangles"].shape == (20 * 4 ** 2, 3)
    h = ft.planet("heights", directions=[[1, 0, 0], [0, 0, 1]], seed=3)
    assert h.shape == (2,) and h.dtype == np.float32
    assert ft.planet("spectrum", lmax=8, seed=3).shape == (9,)
    with pytest.raises(ft.InvalidArgumentError, match="output must be one of"):
        ft.planet("torus")


def test_window_is_the_wholes_samples():
    p = dict(method="midpoint", levels=6, seed=8, erode="land")
    whole = ft.terrain(**p)
    w = ft.window(10, 5, 20, 30, **p)
    assert np.array_equal(w, whole[5:35, 10:30])
    assert w.world_size == pytest.approx(whole.world_size * 19 / 64)


def test_fractalize():
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], np.float32)
    out = ft.fractalize(v, np.array([[0, 1, 2, 3]]), levels=2, seed=1)
    assert out["faces"].shape == (16, 4) and out["vertices"].shape[1] == 3
    assert not np.allclose(out["vertices"][:, 2], 0)  # displaced
    with pytest.raises(ft.InvalidArgumentError, match="face indices"):
        ft.fractalize(v, [[0, 1, 7]])


def test_pov_scene(tmp_path):
    z = ft.terrain(method="midpoint", levels=6, seed=1, erode="land", rivers=True)
    bolt = ft.polyline("fpl3d", depth=5)
    ft.pov_scene(tmp_path / "s.pov", z.terrain, lines=[(bolt, "lightning")], rivers=z.rivers)
    text = (tmp_path / "s.pov").read_text()
    assert "height_field" in text and (tmp_path / "s.terrain.png").is_file()
    with pytest.raises(ft.InvalidArgumentError, match="kind is one of"):
        ft.pov_scene(tmp_path / "t.pov", lines=[(bolt, "zigzag")])


def test_tiles_one_machine_are_the_clis(tmp_path):
    summary = ft.tiles(tmp_path / "py", method="midpoint", levels=6, seed=2, tile=32)
    assert summary["tiles"] == 4 and summary["written"] == 4
    cli("tiles", "--method", "midpoint", "--levels", 6, "--seed", 2, "--tile", 32, "--quiet", "--out", tmp_path / "cli")
    for path in sorted((tmp_path / "cli").rglob("*.png")):
        assert path.read_bytes() == (tmp_path / "py" / path.relative_to(tmp_path / "cli")).read_bytes(), path
    again = ft.tiles(tmp_path / "py", method="midpoint", levels=6, seed=2, tile=32)
    assert again["skipped"] == 4  # resumed: nothing left to write


def test_example_31_runs(tmp_path):
    pytest.importorskip("matplotlib")
    run = subprocess.run([sys.executable, str(EXAMPLES / "31_python_polylines.py"), str(tmp_path / "f.png"),
                          "--quick"], capture_output=True, text=True, timeout=240)
    assert run.returncode == 0, run.stdout + run.stderr
    assert (tmp_path / "f.png").stat().st_size > 10000
    assert "FPL, uniform generator" in run.stdout
