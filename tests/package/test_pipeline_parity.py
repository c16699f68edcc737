# SPDX-License-Identifier: GPL-3.0-or-later
"""The package is the CLI's pipeline: ft.terrain() through ft_terrain_build and
ft.erode()/ft.rivers() through the pipeline's own stages, compared with files
the CLI writes (the same bits), and erode(terrain(p)) == terrain(p, erode=X)
for every preset, periodic and with a sea. Small grids (65^2, 129^2): each
erosion takes well under a second."""

import json
import os
import subprocess

import numpy as np
import pytest

import fracterra as ft
from fracterra.core.erosion import PRESETS

CLI = os.environ.get("FRACTERRA_CLI")


def cli(*args, check=True):
    if not CLI:
        pytest.skip("FRACTERRA_CLI is not set (ctest sets it to the built fracterra)")
    run = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check:
        assert run.returncode == 0, run.stderr
    return run


def cli_terrain(tmp_path, name, *args):
    cli("terrain", *args, "--out", tmp_path / name)
    return np.load(tmp_path / name)


# Midpoint levels 7, periodic (a torus of period 128: the last row and column repeat the first).
PERIODIC = dict(method="midpoint", levels=7, seed=21, periodic=True)
PERIODIC_FLAGS = ("--method", "midpoint", "--levels", 7, "--seed", 21, "--periodic")
# fBm 129^2 with a 30 % sea: the landform's flat sea is erosion's base level.
SEA = dict(method="fbm", size=129, seed=5, sea="fraction", sea_fraction=0.3)
SEA_FLAGS = ("--method", "fbm", "--size", 129, "--seed", 5, "--sea", "fraction", "--sea-fraction", 0.3)


def test_eroded_periodic_terrain_is_the_clis(tmp_path):
    z = ft.terrain(**PERIODIC, erode="rugged_mountains")
    want = cli_terrain(tmp_path, "t.npy", *PERIODIC_FLAGS, "--erode", "rugged_mountains")
    assert z.dtype == np.float32 and np.array_equal(z, want)
    assert z.periodic and z.period_overlap == 1 and np.isnan(z.sea_level)
    assert np.array_equal(z[-1], z[0]) and np.array_equal(z[:, -1], z[:, 0])  # still tiles


def test_eroded_terrain_with_a_sea_is_the_clis(tmp_path):
    z = ft.terrain(**SEA, erode="gentle_valleys", strength=0.5)
    want = cli_terrain(tmp_path, "t.npy", *SEA_FLAGS, "--erode", "gentle_valleys", "--strength", 0.5)
    assert np.array_equal(z, want)
    assert not z.periodic and z.sea_level == pytest.approx(float(ft.terrain(**SEA).min()))


@pytest.mark.parametrize("preset", PRESETS)
def test_erode_of_a_terrain_is_the_terrain_eroded(preset):
    # Periodic (the torus of its true period) and with a sea (its base level), every preset.
    for p in (dict(PERIODIC, levels=6), dict(SEA, size=65)):
        made = ft.terrain(**p)
        eroded, _maps = ft.erode(made, preset=preset, maps=False)
        assert np.array_equal(eroded, ft.terrain(**p, erode=preset)), (preset, p)
        assert eroded.period_overlap == made.period_overlap and eroded.world_size == made.world_size


def test_erode_keeps_the_maps_of_the_pipeline():
    p = dict(PERIODIC, levels=6)
    built = ft.terrain(**p, erode="badlands", maps=True)
    eroded, maps = ft.erode(ft.terrain(**p), "badlands")
    assert np.array_equal(built.terrain, eroded)
    assert set(maps) == set(built.maps) == {"drainage_area", "slope", "curvature", "water_depth", "eroded",
                                            "deposited"}
    for name in maps:
        assert np.array_equal(maps[name], built.maps[name]), name


def test_masks_and_strength_are_the_clis(tmp_path):
    p = dict(method="midpoint", levels=6, seed=3)
    yy, xx = np.mgrid[0:65, 0:65] / 64.0
    mask = np.clip(1.5 - 2 * np.hypot(xx - 0.5, yy - 0.5), 0, 1).astype(np.float32)
    rain = np.clip(xx, 0, 1).astype(np.float32)
    np.save(tmp_path / "mask.npy", mask)
    np.save(tmp_path / "rain.npy", rain)
    z = ft.terrain(**p, erode="Rugged Mountains", strength=0.4, erosion_mask=mask, rain_map=rain)
    want = cli_terrain(tmp_path, "t.npy", "--method", "midpoint", "--levels", 6, "--seed", 3, "--erode",
                       "rugged-mountains", "--strength", 0.4, "--erosion-mask", tmp_path / "mask.npy",
                       "--rain-map", tmp_path / "rain.npy")
    assert np.array_equal(z, want)
    assert not np.array_equal(z, ft.terrain(**p, erode="land", strength=0.4))  # the mask and rain matter
    e, _ = ft.erode(ft.terrain(**p), "land", strength=0.4, erosion_mask=mask, rain_map=rain, maps=False)
    assert np.array_equal(e, z)


def test_rivers_are_the_clis(tmp_path):
    built = ft.terrain(**PERIODIC, erode="land", rivers=True)
    cli("terrain", *PERIODIC_FLAGS, "--erode", "land", "--rivers", tmp_path / "cli.json")
    built.rivers.write(tmp_path / "py.json")
    assert (tmp_path / "py.json").read_bytes() == (tmp_path / "cli.json").read_bytes()
    # The rivers stage alone on the eroded terrain kept in numpy: the same network, and the same
    # terrain carved along it (the pipeline returns the terrain carved).
    eroded = ft.terrain(**PERIODIC, erode="land")
    again = ft.rivers(eroded)
    again.write(tmp_path / "again.json")
    assert (tmp_path / "again.json").read_bytes() == (tmp_path / "cli.json").read_bytes()
    carved = again.carve()
    assert np.array_equal(carved, built.terrain) and carved.period_overlap == 1
    assert np.array_equal(built.terrain, cli_terrain(tmp_path, "t.npy", *PERIODIC_FLAGS, "--erode", "land",
                                                     "--rivers", tmp_path / "again.csv"))
    r = built.rivers
    assert r.segment_count > 3 and r.xyz.shape == (r.offsets[-1], 3)
    assert r.water_mask.shape == built.terrain.shape
    assert set(r.end) <= {"confluence", "sea", "lake", "edge", "sink"}
    doc = json.loads((tmp_path / "cli.json").read_text())
    assert len(doc["polylines"]) == r.segment_count


def test_rivers_with_a_sea_end_in_it(tmp_path):
    built = ft.terrain(**SEA, erode="land", rivers=True)
    cli("terrain", *SEA_FLAGS, "--erode", "land", "--rivers", tmp_path / "cli.json")
    built.rivers.write(tmp_path / "py.json")
    assert (tmp_path / "py.json").read_bytes() == (tmp_path / "cli.json").read_bytes()
    again = ft.rivers(ft.terrain(**SEA, erode="land"))  # the landform's sea is the rivers' too
    assert np.array_equal(again.carve(), built.terrain)
    assert "sea" in set(built.rivers.end) and (built.rivers.water_mask == ft.Rivers.SEA).any()


def test_rivers_write_geojson(tmp_path):
    if not ft.core.binding.library().ft_has_feature(b"gdal"):
        pytest.skip("this build has no GDAL (GeoJSON and GeoPackage are written through OGR)")
    z = ft.terrain(method="midpoint", levels=6, seed=4, erode="land")
    r = ft.rivers(z)
    r.to_geojson(tmp_path / "r.geojson")
    cli("rivers", "--in", _saved(z, tmp_path / "z.npy"), "--out", tmp_path / "cli.geojson")
    assert (tmp_path / "r.geojson").read_bytes() == (tmp_path / "cli.geojson").read_bytes()
    doc = json.loads((tmp_path / "r.geojson").read_text())
    assert doc["type"] == "FeatureCollection" and len(doc["features"]) >= r.segment_count
    r.to_geopackage(tmp_path / "r.gpkg")
    assert (tmp_path / "r.gpkg").stat().st_size > 0


def _saved(z, path):
    ft.save(z, path)
    return path


def test_the_clis_size_and_preset_names():
    assert ft.terrain(method="fbm", size=(96, 64), seed=1).shape == (64, 96)
    assert ft.terrain(method="fbm", size="96x64", seed=1).shape == (64, 96)
    assert ft.terrain(method="fbm", size=72, seed=1).shape == (72, 72)
    one = ft.terrain(method="midpoint", levels=5, seed=2, erode="rugged_mountains")
    for name in ("Rugged Mountains", "rugged-mountains", "RUGGED_MOUNTAINS", "land", "LAND"):
        assert np.array_equal(ft.terrain(method="midpoint", levels=5, seed=2, erode=name), one), name
    with pytest.raises(ft.InvalidArgumentError, match=r"unknown erosion preset 'lava': one of .*land \(Rugged Mountains\)"):
        ft.terrain(levels=5, erode="lava")
    with pytest.raises(ft.InvalidArgumentError, match="size must be"):
        ft.terrain(size="big")


def test_size_is_the_clis(tmp_path):
    z = ft.terrain(method="fbm", size=(96, 64), seed=8)
    assert np.array_equal(z, cli_terrain(tmp_path, "t.npy", "--method", "fbm", "--size", "96x64", "--seed", 8))


def test_keywords_and_docs():
    import inspect
    sig = inspect.signature(ft.terrain)
    for name in ("hurst", "size", "erode", "strength", "erosion_mask", "maps", "rivers", "sea_fraction"):
        assert name in sig.parameters, name
    doc = ft.terrain.__doc__
    assert "strength: " in doc and "world units" in doc
    assert "erode: an erosion preset" in doc and "Rugged Mountains" in doc
    assert "min_area" in inspect.signature(ft.rivers).parameters


def test_a_terrain_keeps_its_world_through_numpy():
    import pickle
    z = ft.terrain(**dict(PERIODIC, levels=5))
    assert (z * 2).period_overlap == 1 and z[::2, ::2].period_overlap == -1  # another grid no longer tiles
    back = pickle.loads(pickle.dumps(z))
    assert (back.world_size, back.period_overlap) == (z.world_size, 1) and np.array_equal(back, z)
    # A plain copy erodes as the grid it is (no torus): another terrain.
    plain = np.array(z)
    assert not isinstance(plain, ft.Terrain) or plain.period_overlap == 1
