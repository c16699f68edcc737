# SPDX-License-Identifier: GPL-3.0-or-later
"""One pipeline, the same bits in every front end: `fracterra terrain
--erode` (the CLI) and core.build_terrain (the binding the add-on uses) call
the library's ft_terrain_build. Checked for a periodic midpoint terrain and a
spectral one (both tile: eroded as a torus) and a bounded fbm one, with and
without erosion. tests/blender/test_erosion.py closes the triangle: Blender's
Erode step against core.build_terrain.

Before the pipeline the CLI eroded only spectral terrains as a torus and the
add-on every periodic one: these cases differed (issue 25)."""

import subprocess

import numpy as np
import pytest

from test_params import _cli

CASES = {
    "periodic midpoint": ({"method": "MIDPOINT", "levels": 6, "seed": 3, "periodic": True},
                          ["--method", "midpoint", "--levels", "6", "--seed", "3", "--periodic"]),
    "spectral": ({"method": "SPECTRAL", "width": 64, "height": 48, "seed": 3},
                 ["--method", "spectral", "--size", "64x48", "--seed", "3"]),
    "bounded fbm": ({"method": "FBM", "width": 50, "height": 40, "seed": 3},
                    ["--method", "fbm", "--size", "50x40", "--seed", "3"]),
}


@pytest.mark.parametrize("preset", ["NONE", "LAND", "VALLEYS"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_cli_and_binding_build_the_same_bits(core, tmp_path, case, preset):
    values, flags = CASES[case]
    out = tmp_path / "t.npy"
    erode = [] if preset == "NONE" else ["--erode", preset.lower()]
    subprocess.run([_cli(), "terrain", *flags, *erode, "--threads", "2", "--out", str(out)], check=True)
    cli = np.load(out)
    hf, maps = core.build_terrain(values, preset=preset, threads=1)
    with hf:
        ours = np.frombuffer(hf.to_array(), dtype=np.float32).reshape(hf.height, hf.width)
    assert maps is None
    assert cli.dtype == np.float32 and cli.shape == ours.shape
    assert np.array_equal(cli, ours), f"{case}, {preset}: {np.count_nonzero(cli != ours)} samples differ"


def test_an_eroded_periodic_midpoint_terrain_still_tiles(core):
    values, _ = CASES["periodic midpoint"]
    hf, maps = core.build_terrain(values, preset="LAND", maps=True)
    with hf:
        z = np.frombuffer(hf.to_array(), dtype=np.float32).reshape(hf.height, hf.width)
    assert np.array_equal(z[-1], z[0]) and np.array_equal(z[:, -1], z[:, 0])
    area = np.frombuffer(maps["drainage_area"], dtype=np.float32).reshape(z.shape)
    assert np.array_equal(area[-1], area[0])


def test_a_window_is_the_wholes_samples_heights_and_maps(core):
    # ft_terrain_build_window (ABI 2.26) through the binding: the samples of the whole, byte for byte.
    values, _ = CASES["periodic midpoint"]
    hf, maps = core.build_terrain(values, preset="LAND", maps=True)
    with hf:
        z = np.frombuffer(hf.to_array(), dtype=np.float32).reshape(hf.height, hf.width)
    x0, y0, w, h = 5, 9, 23, 17
    win, win_maps = core.build_terrain(values, preset="LAND", maps=True, window=(x0, y0, w, h))
    with win:
        assert (win.width, win.height) == (w, h)
        got = np.frombuffer(win.to_array(), dtype=np.float32).reshape(h, w)
    assert np.array_equal(got, z[y0:y0 + h, x0:x0 + w])
    for name, whole in maps.items():
        m = np.frombuffer(whole, dtype=np.float32).reshape(z.shape)
        assert np.array_equal(np.frombuffer(win_maps[name], dtype=np.float32).reshape(h, w), m[y0:y0 + h, x0:x0 + w]), name
    with pytest.raises(core.InvalidArgumentError, match="lies outside"):
        core.build_terrain(values, preset="LAND", window=(z.shape[1] - 3, 0, 4, 4))


def test_custom_erosion_settings_pass_through_and_a_preset_sets_only_its_own(core):
    from fracterra.core import erosion
    values, _ = CASES["bounded fbm"]
    # Strength is not a preset's: it stays the one given, and a stronger run erodes more.
    with core.build_terrain(values, erosion={"strength": 1.0}, preset="SCREE")[0] as strong, \
            core.build_terrain(values, preset="SCREE")[0] as default:
        assert strong.to_array() != default.to_array()
    # A preset is its settings: given by hand with no preset, they make the same terrain.
    own = {name: erosion.preset_values("scree")[name] for name in erosion.PRESET_FIELDS}
    with core.build_terrain(values, erosion=own, preset="NONE")[0] as custom, \
            core.build_terrain(values, preset="SCREE")[0] as scree:
        assert custom.to_array() == scree.to_array()


def test_bad_settings_are_refused_with_the_range(core):
    values, _ = CASES["bounded fbm"]
    with pytest.raises(core.InvalidArgumentError, match=r"evaporation.*\[0, 1\]"):
        core.build_terrain(values, erosion={"evaporation": 2.0})
    with pytest.raises(core.InvalidArgumentError, match="NONE, VALLEYS"):
        core.build_terrain(values, preset="GLACIERS")


@pytest.mark.parametrize("case", sorted(CASES))
def test_cli_and_binding_trace_the_same_rivers(core, tmp_path, case):
    """The rivers stage (ABI 2.20): core.build_terrain_rivers (the add-on's
    Rivers and Lakes) and `fracterra terrain --rivers` give the same rivers,
    and a tiling terrain's water mask wraps back onto its grid."""
    import json
    values, flags = CASES[case]
    out = tmp_path / "r.json"
    subprocess.run([_cli(), "terrain", *flags, "--erode", "valleys", "--threads", "2", "--rivers", str(out)],
                   check=True)
    cli = json.loads(out.read_text())
    rivers = {"rivers_min_area": 0.1}
    hf, _maps, water = core.build_terrain_rivers({**values, **rivers}, core.params.RIVERS_PARAMS, preset="VALLEYS",
                                                 threads=1)
    hf.close()
    assert water.segment_count == len(cli["polylines"])
    want = np.concatenate([np.array(p["points"], dtype=np.float64) for p in cli["polylines"]])
    np.testing.assert_allclose(water.xyz, want, atol=1e-9)
    assert water.mask.shape == (water.ny, water.nx)
    if case != "bounded fbm":  # a torus: no river leaves by an edge, the mask's last row repeats the first
        assert "edge" not in {p["end"] for p in cli["polylines"]}
        if case == "periodic midpoint":
            assert np.array_equal(water.mask[-1], water.mask[0]) and np.array_equal(water.mask[:, -1], water.mask[:, 0])
