# SPDX-License-Identifier: GPL-3.0-or-later
"""The installed fracterra wheel, from outside the source tree: the numpy API
against the CLI's files (same library, same bits), its keyword arguments and
docs from the parameter tables, errors with the library's messages, and the
platform check at import."""

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


def cli(*args):
    if not CLI:
        pytest.skip("FRACTERRA_CLI is not set (ctest sets it to the built fracterra)")
    run = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run.stdout


def test_imported_from_the_venv_with_the_wheels_library():
    assert Path(ft.__file__).resolve().is_relative_to(Path(sys.prefix).resolve()), ft.__file__
    from fracterra.core.binding import library
    lib = library()
    assert Path(lib.path).resolve().parent == Path(ft.__file__).resolve().parent / "lib"
    assert ft.version().startswith("libfracterra ")
    assert ft.__version__ == lib.version


def test_the_wheel_names_its_licence_and_carries_it():
    from importlib import metadata
    dist = metadata.distribution("fracterra")
    assert dist.metadata["License"] == "GPL-3.0-or-later"
    assert "License :: OSI Approved :: GNU General Public License v3 or later (GPLv3+)" in (
        dist.metadata.get_all("Classifier") or [])
    licence = [f for f in dist.files if f.name == "LICENSE"]
    assert licence, [str(f) for f in dist.files if "dist-info" in str(f)]
    assert "GNU GENERAL PUBLIC LICENSE" in licence[0].read_text()


def test_terrain_is_the_clis_terrain(tmp_path):
    z = ft.terrain(method="midpoint", levels=7, hurst=0.8, seed=7)
    assert isinstance(z, np.ndarray) and isinstance(z, ft.Terrain)
    assert z.dtype == np.float32 and z.shape == (129, 129)
    assert z.world_size > 0
    cli("terrain", "--method", "midpoint", "--levels", 7, "--hurst", 0.8, "--seed", 7, "--out", tmp_path / "t.npy")
    assert np.array_equal(z, np.load(tmp_path / "t.npy"))
    # Slicing and arithmetic keep the world size.
    assert (z[::2, ::2] * 2).world_size == z.world_size


def test_other_methods_and_sizes():
    z = ft.terrain(method="fbm", width=96, height=64, seed=3)
    assert z.shape == (64, 96)
    assert not np.array_equal(z, ft.terrain(method="fbm", width=96, height=64, seed=4))


def test_erode_is_the_clis_erosion(tmp_path):
    z = ft.terrain(method="midpoint", levels=6, seed=2)
    e, maps = ft.erode(z, preset="land")
    assert set(maps) == {"drainage_area", "slope", "curvature", "water_depth", "eroded", "deposited"}
    assert all(m.shape == z.shape for m in maps.values())
    ft.save(z, tmp_path / "z.npy")
    cli("erode", "--in", tmp_path / "z.npy", "--preset", "land", "--world-size", z.world_size,
        "--out", tmp_path / "e.npy")
    assert np.array_equal(e, np.load(tmp_path / "e.npy"))
    e2, none = ft.erode(z, "land", maps=False, duration=1000)
    assert none == {} and not np.array_equal(e2, e)


def test_analyze_measures_h_and_drainage():
    # One midpoint realisation of H = 0.8 on 513^2: the aligned variogram (the
    # library's choice on 2^n + 1 grids) is unbiased for midpoint displacement,
    # and one surface's estimate scatters by a few hundredths; 0.1 leaves room.
    z = ft.terrain(method="midpoint", levels=9, hurst=0.8, seed=11)
    a = ft.analyze(z)
    assert abs(a["hurst"] - 0.8) < 0.1, a
    assert a["dimension"] == pytest.approx(3 - a["hurst"])
    assert a["estimator"] == "variogram_aligned"
    assert {"hack_h", "theta"} <= set(a["drainage"])
    spectral = ft.analyze(z, "spectral", drainage=False)
    assert spectral["estimator"] == "spectral" and "drainage" not in spectral


def test_save_and_load_round_trip(tmp_path):
    z = ft.terrain(method="fbm", width=40, height=30, seed=5, world_size=250)
    for name in ("t.npy", "t.exr", "t.tif"):
        ft.save(z, tmp_path / name)
        back = ft.load(tmp_path / name)
        assert np.array_equal(back, z), name
    # Every format records the world size (.npy in its sidecar t.npy.json).
    assert ft.load(tmp_path / "t.exr").world_size == pytest.approx(250)
    assert ft.load(tmp_path / "t.npy").world_size == pytest.approx(250)
    assert json.loads((tmp_path / "t.npy.json").read_text())["world_size"] == pytest.approx(250)
    for name in ("t.png", "t.pgm", "t.raw", "t.tif"):
        ft.save(z, tmp_path / name)
        assert ft.load(tmp_path / name).world_size == pytest.approx(250), name
    ft.save(np.zeros((3, 4)), tmp_path / "plain.npy")  # any 2-D array; it records no world size
    plain = ft.load(tmp_path / "plain.npy")
    assert plain.shape == (3, 4) and plain.world_size == 0


def test_a_file_without_a_world_size_warns_when_used(tmp_path, capfd):
    z = ft.terrain(method="midpoint", levels=5, seed=1, world_size=20)
    ft.save(z, tmp_path / "t.npy")
    (tmp_path / "t.npy.json").unlink()
    e, _ = ft.erode(ft.load(tmp_path / "t.npy"), "land", maps=False)
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "records no world size" in err[0] and "10 world units" in err[0], err
    assert e.world_size == 10
    ft.erode(z, "land", maps=False)  # a Terrain that knows its world: no warning
    assert capfd.readouterr().err == ""


def test_splat_weights_sum_exactly():
    z = ft.terrain(method="midpoint", levels=6, seed=2, sigma=3)
    e, maps = ft.erode(z, "land")
    w = ft.splat(e, maps)
    assert w.shape == (65, 65, 4) and w.dtype == np.uint16
    assert np.all(w.sum(axis=2) == 255)
    rgb = ft.splat(e, maps, color=True)
    assert rgb.shape == (65, 65, 3) and 0 <= rgb.min() and rgb.max() <= 1
    two = ft.splat(e, rules=[{"name": "low", "height_max": 0.5}, {"name": "high", "height_min": 0.5}],
                   total=65535)
    assert np.all(two.sum(axis=2) == 65535)


def test_keywords_and_docs_come_from_the_tables():
    sig = inspect.signature(ft.terrain)
    assert sig.parameters["hurst"].default is None
    assert sig.parameters["hurst"].kind is inspect.Parameter.KEYWORD_ONLY
    doc = ft.terrain.__doc__
    assert "hurst: " in doc and "range [0, 1]" in doc
    assert "method: " in doc and "midpoint" in doc
    assert "erodibility" in inspect.signature(ft.erode).parameters


def test_errors_carry_the_librarys_message():
    with pytest.raises(ft.InvalidArgumentError, match=r"hurst must be in \[0, 1\], got 1\.5"):
        ft.terrain(hurst=1.5)
    with pytest.raises(TypeError, match="unknown setting 'hurts'"):
        ft.terrain(hurts=0.5)
    with pytest.raises(ft.InvalidArgumentError, match="method must be one of"):
        ft.terrain(method="diamond")
    with pytest.raises(ft.FracterraError, match="unknown erosion preset"):
        ft.erode(np.zeros((8, 8)), "lava")
    with pytest.raises(ft.FracterraError, match="cannot|not"):
        ft.load("/nonexistent/t.png")


def test_an_unsupported_platform_is_named_at_import():
    code = "import platform; platform.machine = lambda: 'riscv64'; import fracterra"
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert run.returncode != 0
    assert "ImportError" in run.stderr and "riscv64" in run.stderr and "linux-x86_64" in run.stderr


def test_tiles_runs_as_a_module(tmp_path):
    pytest.importorskip("distributed")
    run = subprocess.run([sys.executable, "-m", "fracterra.tiles", "--method", "midpoint", "--levels", "6",
                          "--tile", "32", "--workers", "1", "--quiet", "--out", str(tmp_path / "set")],
                         capture_output=True, text=True, timeout=240)
    assert run.returncode == 0, run.stderr
    # runpy's "found in sys.modules" warning, which `import fracterra` importing its tiles module
    # eagerly printed in the driver and in every worker
    assert "found in sys.modules" not in run.stderr, run.stderr
    summary = json.loads(run.stdout.strip().splitlines()[-1])
    assert summary["tiles"] == 4
    assert (tmp_path / "set" / "manifest.json").is_file()
