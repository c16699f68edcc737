# SPDX-License-Identifier: GPL-3.0-or-later
"""The ctypes binding of ft_erode (blender_addon/fracterra/core/erosion.py),
outside Blender: presets as the library defines them, the eroded terrain and
its maps, bad settings refused naming the field, cancel from the progress
callback."""

import pytest


@pytest.fixture(scope="module")
def erosion(core):
    from fracterra.core import erosion
    return erosion


def _terrain(core, levels=6):
    return core.generate_terrain(method="MIDPOINT", levels=levels, hurst=0.8, sigma=1.0, seed=7, world_size=10.0)


def test_presets_are_the_librarys(erosion):
    # Every preset is a run of the landscape model (years), no expert pass;
    # the old ids are aliases of the new presets.
    for preset in erosion.PRESETS:
        values = erosion.preset_values(preset)
        assert values["duration"] > 0 and values["strength"] == 0.5, preset
        assert all(values[name] == 0 for name in erosion.COUNTS), preset
        assert erosion.requested(values)
        assert not erosion.requested(values | {"strength": 0.0})
    assert erosion.preset_values("valleys") == erosion.preset_values("gentle_valleys")
    assert erosion.preset_values("land") == erosion.preset_values("Rugged Mountains")


def test_presets_fit_no_uplift_any_more(core, erosion):
    with _terrain(core) as hf:
        assert erosion.fitted_uplift("valleys", hf) == {"uplift": 0.0, "uplift_follows_terrain": False}
        with pytest.raises(core.InvalidArgumentError, match="preset"):
            erosion.fitted_uplift("glaciers", hf)


def test_an_erosion_mask_keeps_its_outside(core, erosion):
    # Mask 0 on the right third (a 4 x 2 map ramps over the middle third):
    # nothing there is lowered.
    with _terrain(core) as hf:
        before = hf.to_array()
        eroded, _ = erosion.erode_arrays(hf, preset="badlands", maps=False,
                                         erosion_mask=(4, 2, [1, 1, 0, 0, 1, 1, 0, 0]))
    with eroded:
        after = eroded.to_array()
    right = [i for i in range(65 * 65) if 3 * (i % 65) > 2 * 64]
    assert all(after[i] >= before[i] for i in right)
    assert any(after[i] < before[i] - 1e-4 for i in range(65 * 65) if i % 65 < 16)
    with _terrain(core) as hf, pytest.raises(core.InvalidArgumentError, match=r"rain_map's values must be in \[0, 1\]"):
        erosion.erode(hf, preset="badlands", rain_map=(2, 2, [0.0, 2.0, 1.0, 1.0]))


def test_land_preset_erodes_and_returns_every_map(core, erosion):
    with _terrain(core) as hf:
        before = hf.to_array()
        eroded, maps = erosion.erode_arrays(hf, preset="land")
    with eroded:
        after = eroded.to_array()
        assert (eroded.width, eroded.height) == (65, 65)
    assert sorted(maps) == sorted(erosion.MAPS)
    assert all(len(m) == 65 * 65 for m in maps.values())
    changed = sum(1 for a, b in zip(before, after) if abs(a - b) > 1e-6)
    assert changed > 65 * 65 // 2, "erosion changed too few cells"
    cell_area = (10.0 / 64) ** 2
    # The whole grid drains out: the largest drainage areas add up to at least
    # a good part of the grid (each cell counts its own area).
    assert max(maps["drainage_area"]) > 50 * cell_area
    assert min(maps["drainage_area"]) == pytest.approx(cell_area, rel=1e-5)
    assert max(maps["eroded"]) > 0
    # The fans preset lays sediment down; water is left only by the expert
    # rain passes, which the presets do not run.
    with _terrain(core) as hf:
        fans, fan_maps = erosion.erode_arrays(hf, preset="alluvial_fans")
        fans.close()
    assert max(fan_maps["deposited"]) > 0
    assert max(maps["water_depth"]) == 0


def test_settings_override_the_preset(core, erosion):
    with _terrain(core, 5) as hf:
        a, _ = erosion.erode_arrays(hf, preset="scree", maps=False)
        b, _ = erosion.erode_arrays(hf, preset="scree", values={"talus_degrees": 20.0}, maps=False)
        with a, b:
            assert a.to_array() != b.to_array()


def test_bad_settings_are_refused_naming_the_field(core, erosion):
    with _terrain(core, 4) as hf:
        with pytest.raises(core.InvalidArgumentError, match="rain"):
            erosion.erode(hf, values={"hydraulic_iterations": 2, "rain": -1.0})
        with pytest.raises(core.InvalidArgumentError, match="gentle_valleys"):
            erosion.erode(hf, preset="volcano")


def test_cancel_from_the_progress_callback(core, erosion):
    seen = []

    def progress(fraction):
        seen.append(fraction)
        return fraction > 0.2

    with _terrain(core, 6) as hf:
        with pytest.raises(core.CancelledError):
            erosion.erode(hf, preset="land", progress=progress)
    assert seen and max(seen) < 1.0
