# SPDX-License-Identifier: GPL-3.0-or-later
"""The grid sizes Blender can hold are decided from the size alone: the
boundary is the first array past 2^31 - 1 bytes (here the face corners at
12 bytes each), and levels 13 -- the size that crashed -- is refused."""

from fracterra.core import mesh_limits, params
from fracterra.core.errors import TooLargeError

import pytest


def test_counts_match_the_library_grid(core):
    c = core.grid.grid_counts(7, 5)
    assert mesh_limits.quad_grid_counts(7, 5) == {
        "vertices": c.vertices, "edges": c.edges, "face corners": c.loops, "faces": c.faces}


def test_boundary_is_the_face_corner_array_of_2_gib():
    # 4 (n - 1)^2 corners x 12 bytes <= 2^31 - 1  <=>  n - 1 <= 6688.
    assert mesh_limits.too_large(6689, 6689) is None
    reason = mesh_limits.too_large(6690, 6690)
    assert "face corners" in reason and "178,956,970" in reason


def test_levels_12_pass_and_13_are_refused_before_any_work():
    assert mesh_limits.too_large(4097, 4097) is None
    with pytest.raises(TooLargeError, match="Refused before generating: a 8193 x 8193 grid"):
        mesh_limits.check_grid(*params.grid_shape({"method": "MIDPOINT", "levels": 13}))
    assert params.grid_shape({"method": "FBM", "levels": 13, "width": 300, "height": 20}) == (300, 20)


def test_estimate_names_vertices_and_memory():
    assert mesh_limits.estimate(4097, 4097) == "16.8 M vertices, about 5.0 GB of memory"
