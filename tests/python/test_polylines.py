# SPDX-License-Identifier: GPL-3.0-or-later
"""Polylines, measures, coastlines and POV-Ray scenes through the binding."""


import pytest


def test_fpl_on_a_base_segment_has_2_to_the_depth_plus_one_vertices(core):
    with core.generate_polylines(method="FPL", depth=4, seed=2, base=[(0, 0, 0), (3, 4, 0)]) as pl:
        (line, radii), = pl.lines()
    assert len(line) == 17 and len(radii) == 17
    assert line[0] == (0, 0, 0) and line[-1] == (3, 4, 0)


def test_same_seed_same_polyline(core):
    with core.generate_polylines(depth=8, seed=9, spread=0.3) as a, core.generate_polylines(depth=8, seed=9, spread=0.3) as b:
        assert a.xyz() == b.xyz()


def test_measures_of_a_straight_line(core):
    with core.Polylines.from_lines([[(0, 0, 0), (0.5, 0, 0), (1, 0, 0)]]) as pl:
        s = pl.measure()
    assert s["eta"] == 0 and s["chi"] == 0 and s["gamma"] == pytest.approx(1.0)


def test_polylines_round_trip(core):
    lines = [[(0, 0, 0), (1, 0, 0)], [(0, 1, 0), (1, 1, 0), (2, 2, 1)]]
    radii = [[0.1, 0.2], [0.3, 0.3, 0.3]]
    with core.Polylines.from_lines(lines, radii) as pl:
        assert pl.line_count == 2 and pl.vertex_count == 5
        assert pl.lines() == [(lines[0], radii[0]), (lines[1], radii[1])]


def test_polylines_from_numpy_arrays_equal_the_same_lines(core):
    import numpy as np
    lines = [[(0, 0, 0), (1, 0, 0)], [(0, 1, 0), (1, 1, 0), (2, 2, 1)]]
    radii = [[0.1, 0.2], [0.3, 0.3, 0.3]]
    xyz = np.array([p for line in lines for p in line], dtype=np.float64)  # (5, 3): flattened by the binding
    offsets = np.array([0, 2, 5], dtype=np.int64)
    for rad in (np.array([0.1, 0.2, 0.3, 0.3, 0.3]), np.array([0.1, 0.2, 0.3, 0.3, 0.3], dtype=np.float32)):
        with core.Polylines.from_arrays(xyz, rad, offsets) as pl:
            got = pl.lines()
        assert [line for line, _ in got] == lines
        assert [r for _, line in got for r in line] == pytest.approx([0.1, 0.2, 0.3, 0.3, 0.3], rel=1e-7)
    with core.Polylines.from_arrays(xyz.ravel(), None, offsets) as pl:
        assert pl.radii().tolist() == [0.0] * 5


def test_bad_spread_is_the_library_message(core):
    with pytest.raises(core.InvalidArgumentError, match="spread"):
        core.generate_polylines(spread=-1.0)


def test_coastline_at_the_median_lies_at_the_median_between_its_samples(core):
    with core.generate_terrain(levels=5, seed=4) as hf, core.coastline(hf, 0.5, quantile=True) as pl:
        lines = pl.lines()
        h, n = hf.to_array(), hf.width
    # The median as the library defines its quantiles (NumPy's default, linear between
    # order statistics); 33^2 samples: the middle one.
    level = sorted(h)[len(h) // 2]
    assert lines
    for line, _ in lines:
        for x, y, z in line:
            assert z == pytest.approx(level, abs=1e-6)
            # Marching squares puts every vertex on a cell edge, between two samples that
            # straddle the level (land >= level on one side, sea on the other).
            if x == int(x):
                a, b = h[int(y) * n + int(x)], h[min(int(y) + 1, n - 1) * n + int(x)]
            else:
                assert y == int(y)
                a, b = h[int(y) * n + int(x)], h[int(y) * n + min(int(x) + 1, n - 1)]
            assert min(a, b) - 1e-6 <= level <= max(a, b) + 1e-6, (x, y, a, b)


def test_hurst_estimate_of_a_midpoint_terrain(core):
    # The dyadic-aligned variogram is exact in expectation for midpoint displacement;
    # one 257^2 realisation scatters by a few hundredths: 0.1 is a loose bound.
    with core.generate_terrain(levels=8, seed=1, hurst=0.6) as hf:
        r = core.hurst_of_heightfield(hf)
    assert r["hurst"] == pytest.approx(0.6, abs=0.1)
    assert r["dimension"] == pytest.approx(3 - r["hurst"])
    assert r["estimator"] == "variogram_aligned"  # AUTO on a 2^n + 1 grid
    assert "2^n + 1" in r["reason"]


def test_auto_hurst_estimator_follows_the_grid(core):
    # The library's recommendation (FT_HURST_AUTO): the same value as the named method it chose.
    with core.generate_terrain(method="FBM", width=300, height=260, seed=3) as hf:
        auto = core.hurst_of_heightfield(hf)
        spectral = core.hurst_of_heightfield(hf, method="SPECTRAL")
    assert auto["estimator"] == "spectral" and auto["auto_reason"] == 2
    assert auto["hurst"] == spectral["hurst"]
    with core.generate_terrain(method="FBM", width=100, height=90, seed=3) as hf:
        assert core.hurst_of_heightfield(hf)["estimator"] == "variogram"


def test_pov_scene_is_written(core, tmp_path):
    from fracterra.core import povray
    with core.generate_terrain(levels=4, seed=1) as hf, core.generate_polylines(depth=3) as pl:
        povray.write_scene(str(tmp_path / "s.pov"), terrain=hf, world_size_x=10, world_size_y=10,
                           line_sets=[(pl, "LINE", 0.0)], camera={"azimuth": 30, "elevation": 40},
                           sun={"azimuth": 200, "elevation": 30})
    assert "height_field" in (tmp_path / "s.pov").read_text()
    assert any(p.suffix == ".png" for p in tmp_path.iterdir())


def test_pov_scene_into_a_missing_folder_is_an_io_error(core, tmp_path):
    from fracterra.core import povray
    with pytest.raises(core.FracterraError) as e:
        with core.generate_terrain(levels=3) as hf:
            povray.write_scene(str(tmp_path / "missing" / "s.pov"), terrain=hf)
    assert e.value.status == 4  # FT_ERR_IO


def test_fractalize_a_quad_grows_faces_by_four_per_level(core):
    import array
    from fracterra.core import subdiv
    quad = subdiv.Mesh.create(array.array("f", [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]),
                              array.array("i", [4]), array.array("i", [0, 1, 2, 3]))
    with quad, subdiv.fractalize(quad, levels=2, sigma=0.1, seed=3) as out:
        assert len(out.face_sizes()) == 16 and set(out.face_sizes()) == {4}
        assert len(out.positions()) == 3 * 25
    with pytest.raises(core.InvalidArgumentError, match="levels"):
        with subdiv.Mesh.create(array.array("f", [0, 0, 0, 1, 0, 0, 1, 1, 0]), array.array("i", [3]),
                                array.array("i", [0, 1, 2])) as tri:
            subdiv.fractalize(tri, levels=0)
