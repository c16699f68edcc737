# SPDX-License-Identifier: GPL-3.0-or-later
"""The splat colours as the add-on takes them (core.splat.linear_rgba)."""

import numpy as np
import pytest


def test_linear_rgba_is_the_colours_decoded_with_progress_and_cancel(core):
    """The library's linear RGBA is colors() decoded by the sRGB formula
    (numpy's float32 decoding within 2.4e-7 of the library's float64 one),
    alpha 1; the progress rises to 1 and a True from it raises
    CancelledError. (Seen to fail with the colours left in sRGB.)"""
    from fracterra.core import splat
    from fracterra.core.errors import CancelledError
    with core.generate_terrain(method="FBM", width=65, height=33, seed=2) as hf:
        want = splat.linear_from_srgb(splat.colors(hf))
        seen = []
        got = splat.linear_rgba(hf, progress=lambda f: seen.append(f)).reshape(-1, 4)
        np.testing.assert_allclose(got[:, :3], want, rtol=0, atol=1e-6)
        assert np.all(got[:, 3] == 1.0)
        assert seen == sorted(seen) and seen[-1] == 1.0
        with pytest.raises(CancelledError):
            splat.linear_rgba(hf, progress=lambda f: f > 0.5)
