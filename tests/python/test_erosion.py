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
    valleys = erosion.preset_values("valleys")
    assert valleys["fluvial_steps"] > 0 and valleys["uplift"] > 0
    assert valleys["hydraulic_iterations"] == 0 and valleys["thermal_iterations"] == 0
    land = erosion.preset_values("land")
    assert all(land[name] > 0 for name in erosion.COUNTS)
    assert not erosion.requested(erosion.preset_values("land") | {name: 0 for name in erosion.COUNTS})
    assert erosion.requested(land)


def test_a_presets_uplift_is_fitted_to_the_terrain(core, erosion):
    # The rate that raises the terrain by its relief over the preset's run.
    valleys = erosion.preset_values("valleys")
    with _terrain(core) as hf:
        heights = hf.to_array()
        relief = max(heights) - min(heights)
        fitted = erosion.fitted_uplift("valleys", hf)
        assert fitted["uplift"] == pytest.approx(relief / (valleys["fluvial_steps"] * valleys["fluvial_dt"]), rel=1e-9)
        assert fitted["uplift_follows_terrain"] is True
        assert erosion.fitted_uplift("rain", hf)["uplift"] == 0.0
        with pytest.raises(core.InvalidArgumentError, match="preset"):
            erosion.fitted_uplift("glaciers", hf)


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
    # Deposits are measured against the input plus the fluvial uplift (so the
    # uplift never shows as deposit); the rain alone lays sediment down.
    with _terrain(core) as hf:
        rained, rain_maps = erosion.erode_arrays(hf, preset="rain")
        rained.close()
    assert max(rain_maps["deposited"]) > 0
    assert max(maps["water_depth"]) > 0


def test_settings_override_the_preset(core, erosion):
    with _terrain(core, 5) as hf:
        a, _ = erosion.erode_arrays(hf, preset="scree", maps=False)
        b, _ = erosion.erode_arrays(hf, preset="scree", values={"talus_degrees": 60.0}, maps=False)
        with a, b:
            assert a.to_array() != b.to_array()


def test_bad_settings_are_refused_naming_the_field(core, erosion):
    with _terrain(core, 4) as hf:
        with pytest.raises(core.InvalidArgumentError, match="rain"):
            erosion.erode(hf, values={"hydraulic_iterations": 2, "rain": -1.0})
        with pytest.raises(core.InvalidArgumentError, match="valleys"):
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
