# SPDX-License-Identifier: GPL-3.0-or-later
"""Bad input from Python is an exception naming what is allowed (a
FracterraError subclass, or TypeError for a wrong type or keyword), checked
before any pointer reaches C: never a crash, never a silent wrong answer.
Each case runs in this interpreter, so a crash would fail the whole suite."""

import numpy as np
import pytest

import fracterra as ft

Z = np.linspace(0, 1, 17 * 17, dtype=np.float32).reshape(17, 17)


@pytest.mark.parametrize("fn", [lambda a: ft.erode(a, "land"), ft.analyze, ft.rivers, ft.splat,
                                lambda a: ft.save(a, "/tmp/never-written.png")])
def test_every_function_checks_its_array(fn):
    with pytest.raises(TypeError, match=r"real numbers.*complex"):
        fn(Z.astype(np.complex64))
    with pytest.raises(TypeError, match="real numbers.*dtype <U"):
        fn(np.array([["a", "b"], ["c", "d"]]))
    with pytest.raises(TypeError, match="2-D numpy array"):
        fn("terrain.png")
    with pytest.raises(ft.InvalidArgumentError, match=r"2-D array .* 3 dimensions of shape \(2, 17, 17\)"):
        fn(np.stack([Z, Z]))
    with pytest.raises(ft.InvalidArgumentError, match="2-D array"):
        fn(Z[0])
    with pytest.raises(ft.InvalidArgumentError, match="at least 1 x 1"):
        fn(np.zeros((0, 5), np.float32))
    bad = Z.copy()
    bad[3, 4] = np.nan
    with pytest.raises(ft.InvalidArgumentError, match="finite.*1 NaN or infinite samples, the first at row 3, column 4"):
        fn(bad)
    bad[3, 4] = np.inf
    with pytest.raises(ft.InvalidArgumentError, match="finite"):
        fn(bad)


def test_views_are_read_as_the_arrays_they_show():
    # Non-contiguous and Fortran-ordered arrays are numpy's ordinary views: read as the values they show.
    z = ft.terrain(method="midpoint", levels=5, seed=3)
    t = np.asarray(z).T
    assert not t.flags.c_contiguous
    assert np.array_equal(ft.erode(t, "land", maps=False)[0], ft.erode(np.ascontiguousarray(t), "land", maps=False)[0])
    strided = np.asarray(z)[::2, ::2]
    assert np.array_equal(ft.analyze(strided, drainage=False)["hurst"],
                          ft.analyze(strided.copy(), drainage=False)["hurst"])
    # Integer and float64 heights are converted to float32.
    assert ft.analyze(np.asarray(z, np.float64), drainage=False)["hurst"] == ft.analyze(z, drainage=False)["hurst"]


def test_unknown_keywords_name_the_allowed_ones():
    with pytest.raises(TypeError, match=r"unknown setting 'hurts' \(did you mean hurst\?\).*levels"):
        ft.terrain(hurts=0.5)
    with pytest.raises(TypeError, match="unknown setting 'strenght'.*strength"):
        ft.erode(Z, "land", strenght=2)
    with pytest.raises(TypeError, match="unknown setting 'min_aera'.*min_area"):
        ft.rivers(Z, min_aera=5)


def test_wrong_types_of_settings():
    with pytest.raises(TypeError, match="levels takes an integer, got 'x'"):
        ft.terrain(levels="x")
    with pytest.raises(TypeError, match="levels takes an integer, got 5.5"):
        ft.terrain(levels=5.5)
    with pytest.raises(TypeError, match="periodic takes True or False"):
        ft.terrain(levels=5, periodic="yes")
    with pytest.raises(ft.InvalidArgumentError, match="method must be one of midpoint"):
        ft.terrain(method="diamond")
    with pytest.raises(TypeError, match="size must be"):
        ft.terrain(size=2.5)
    with pytest.raises(TypeError, match="rivers is True, False or a dict"):
        ft.terrain(levels=5, rivers="yes")
    # The library's own ranges, with its message.
    with pytest.raises(ft.InvalidArgumentError, match=r"hurst must be in \[0, 1\], got 1\.5"):
        ft.terrain(hurst=1.5)


def test_masks_are_checked():
    p = dict(method="midpoint", levels=5, seed=1, erode="land")
    with pytest.raises(ft.InvalidArgumentError, match=r"the erosion mask is 40 x 10 samples .* 33 x 33"):
        ft.terrain(**p, erosion_mask=np.ones((10, 40), np.float32))
    with pytest.raises(ft.InvalidArgumentError, match=r"the rain map must hold values in \[0, 1\], got \[0, 2\]"):
        ft.terrain(**p, rain_map=np.linspace(0, 2, 33 * 33).reshape(33, 33))
    with pytest.raises(ft.InvalidArgumentError, match="the erosion mask must be a 2-D array"):
        ft.erode(Z, "land", erosion_mask=np.ones(17))
    # The terrain's proportions at another resolution are resampled, as in the CLI.
    ft.terrain(**p, erosion_mask=np.ones((17, 17), np.float32))


def test_library_errors_are_fracterra_errors():
    with pytest.raises(ft.FracterraError, match="unknown erosion preset"):
        ft.erode(Z, "lava")
    with pytest.raises(ft.TooLargeError):
        ft.terrain(method="fbm", size=(65536, 65536))
    with pytest.raises(ft.FracterraError):
        ft.load("/nonexistent/t.npy")
