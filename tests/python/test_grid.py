# SPDX-License-Identifier: GPL-3.0-or-later
"""Grid-mesh arrays filled by the library, checked against an independent
Python description of the same grid."""

import math

import pytest


def test_counts_of_a_grid(core):
    with core.generate_terrain(levels=2) as hf:  # 5 x 5
        g = core.grid_arrays(hf, 4.0)
    assert (g.vertex_count, g.edge_count, g.face_count, g.loop_count) == (25, 40, 16, 64)
    assert len(g.co) == 75 and len(g.edge_vertices) == 80 and len(g.loop_vertices) == 64
    assert len(g.uv) == 128


def test_vertices_span_the_world_size_and_carry_the_heights(core):
    with core.generate_terrain(levels=3, seed=8) as hf:
        h = hf.to_array()
        g = core.grid_arrays(hf, 10.0)
    n = 9
    for row in range(n):
        for col in range(n):
            x, y, z = g.co[3 * (row * n + col):3 * (row * n + col) + 3]
            assert x == pytest.approx((col / 8 - 0.5) * 10.0)
            assert y == pytest.approx((row / 8 - 0.5) * 10.0)
            assert z == h[row * n + col]  # bit-identical heights


def test_non_square_grid_keeps_the_sample_spacing(core):
    with core.Heightfield.from_values(5, 3, [0.0] * 15) as hf:
        g = core.grid_arrays(hf, 8.0)
    ys = sorted({g.co[3 * i + 1] for i in range(15)})
    assert ys == [-2.0, 0.0, 2.0]  # spacing 2 in x and y


def test_sea_level_flattens_lower_heights(core):
    values = [-2.0, -1.0, 0.0, 1.0]
    with core.Heightfield.from_values(2, 2, values) as hf:
        g = core.grid_arrays(hf, 1.0, z_floor=-0.5)
    assert [g.co[3 * i + 2] for i in range(4)] == [-0.5, -0.5, 0.0, 1.0]


def test_topology_is_a_consistent_quad_grid(core):
    nx, ny = 4, 3
    with core.Heightfield.from_values(nx, ny, [0.0] * (nx * ny)) as hf:
        g = core.grid_arrays(hf, 1.0)
    edges = [tuple(g.edge_vertices[2 * e:2 * e + 2]) for e in range(g.edge_count)]
    # Every edge joins grid neighbours, and each neighbour pair appears once.
    expected = {(r * nx + c, r * nx + c + 1) for r in range(ny) for c in range(nx - 1)}
    expected |= {(r * nx + c, (r + 1) * nx + c) for r in range(ny - 1) for c in range(nx)}
    assert set(edges) == expected and len(edges) == len(expected)
    for f in range(g.face_count):
        start, total = g.loop_starts[f], g.loop_totals[f]
        assert (start, total) == (4 * f, 4)
        corners = [g.loop_vertices[start + k] for k in range(4)]
        row, col = divmod(f, nx - 1)
        v = row * nx + col
        assert corners == [v, v + 1, v + nx + 1, v + nx]  # counter-clockwise from +z
        for k in range(4):
            a, b = corners[k], corners[(k + 1) % 4]
            assert set(edges[g.loop_edges[start + k]]) == {a, b}


def test_uvs_span_zero_to_one(core):
    with core.Heightfield.from_values(3, 3, [0.0] * 9) as hf:
        g = core.grid_arrays(hf, 1.0)
    us = g.uv[0::2]
    vs = g.uv[1::2]
    assert min(us) == 0.0 and max(us) == 1.0 and min(vs) == 0.0 and max(vs) == 1.0
    assert list(g.uv[:8]) == [0.0, 0.0, 0.5, 0.0, 0.5, 0.5, 0.0, 0.5]


def test_too_small_buffers_are_rejected(core):
    import array
    from ctypes import c_float
    from fracterra.core.terrain import as_pointer
    lib = core.library()
    small = array.array("f", [0.0]) * 10
    with pytest.raises(core.InvalidArgumentError, match="uv holds 10 elements"):
        lib.check(lib.ft_grid_uvs(3, 3, as_pointer(small, c_float), len(small)))
    with pytest.raises(core.InvalidArgumentError, match="nx must be in 2..65536"):
        lib.check(lib.ft_grid_uvs(1, 3, as_pointer(small, c_float), len(small)))


def test_nan_world_size_is_rejected(core):
    with core.Heightfield.from_values(2, 2, [0.0] * 4) as hf:
        with pytest.raises(core.InvalidArgumentError, match="world_size_x"):
            core.vertices(hf, math.nan, 1.0)


def test_grid_heights_rewrite_only_the_z_of_an_xyz_array(core):
    # ft_grid_heights serves hosts that keep their vertex array: with stride 3 and
    # a pointer to the first z it rewrites heights in place and leaves x, y alone.
    import array
    from ctypes import POINTER, addressof, c_float, cast
    from fracterra.core.terrain import as_pointer
    lib = core.library()
    values = [-2.0, -1.0, 0.0, 1.0, 2.0, 3.0]
    with core.Heightfield.from_values(3, 2, values) as hf:
        co = array.array("f", [7.0]) * 18
        first_z = cast(addressof(as_pointer(co, c_float)) + 2 * 4, POINTER(c_float))
        lib.check(lib.ft_grid_heights(hf.handle, -0.5, first_z, 3, len(co) - 2))
        assert list(co[2::3]) == [-0.5, -0.5, 0.0, 1.0, 2.0, 3.0]
        assert list(co[0::3]) == [7.0] * 6 and list(co[1::3]) == [7.0] * 6
        z = array.array("f", [0.0]) * 6
        lib.check(lib.ft_grid_heights(hf.handle, core.grid.NO_FLOOR, as_pointer(z, c_float), 1, len(z)))
        assert list(z) == values
        with pytest.raises(core.InvalidArgumentError):
            lib.check(lib.ft_grid_heights(hf.handle, core.grid.NO_FLOOR, as_pointer(z, c_float), 1, 5))
        with pytest.raises(core.InvalidArgumentError):
            lib.check(lib.ft_grid_heights(hf.handle, core.grid.NO_FLOOR, as_pointer(z, c_float), 0, 6))


def test_height_and_slope_in_bands_are_numpy_gradients_of_the_whole_grid(core):
    """The attributes the worker computes in bands of rows (a 4097^2 grid at
    once took 4.6 s of Blender's main thread) are the whole-grid formula's to
    the bit, on a grid whose bands are uneven, with a report after each band
    rising to 1; a True from the callback stops it. (Seen to fail with each
    band's first and last rows differenced one-sided, as at the grid's
    edge.)"""
    import numpy as np
    from fracterra.core.errors import CancelledError
    from fracterra.core.grid import height_slope
    with core.generate_terrain(method="FBM", width=53, height=37, seed=4) as hf:
        g = core.grid_arrays(hf, 10.0)
    nx, ny = 53, 37
    xyz = np.frombuffer(g.co, dtype=np.float32).reshape(ny, nx, 3).astype(np.float64)
    z = xyz[:, :, 2]
    want_height = ((z - z.min()) / (z.max() - z.min())).astype(np.float32).ravel()
    gy, gx = np.gradient(z, (xyz[-1, 0, 1] - xyz[0, 0, 1]) / (ny - 1), (xyz[0, -1, 0] - xyz[0, 0, 0]) / (nx - 1))
    want_slope = (np.arctan(np.hypot(gx, gy)) / (np.pi / 2)).astype(np.float32).ravel()
    seen = []
    height, slope = height_slope(g.co, nx, ny, progress=lambda f: seen.append(f), bands=7)
    assert np.array_equal(height, want_height)
    assert np.array_equal(slope, want_slope)
    assert seen == sorted(seen) and len(seen) == 7 and seen[-1] == 1.0
    with pytest.raises(CancelledError):
        height_slope(g.co, nx, ny, progress=lambda f: f > 0.4, bands=7)
