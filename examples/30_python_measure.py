# SPDX-License-Identifier: GPL-3.0-or-later
"""Generate, erode and measure a terrain from Python, and plot its variogram
with the Hurst exponent the library fits.

    python3 -m venv --system-site-packages venv
    venv/bin/pip install --no-index --no-build-isolation build/python/fracterra-*.whl
    venv/bin/python examples/30_python_measure.py docs/images/python-measure.png

The variogram gamma(lag) = mean((z(x + lag) - z(x))^2) over rows and columns
is computed here with numpy, independently of the library; for fBm it grows
as lag^(2H). The lines are the library's fit (ft.analyze: H, and the band of
lags it fitted), drawn with slope 2H through the numpy points of that band.
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LightSource  # noqa: E402

import fracterra as ft  # noqa: E402


def variogram(z, lags):
    return np.array([np.mean(np.concatenate([(z[:, k:] - z[:, :-k]).ravel() ** 2,
                                             (z[k:, :] - z[:-k, :]).ravel() ** 2])) for k in lags])


def main(out):
    z = ft.terrain(method="midpoint", levels=9, hurst=0.8, sigma=1.0, seed=7, world_size=10)
    e, maps = ft.erode(z, preset="land")
    lags = np.unique(np.round(np.geomspace(1, 128, 22)).astype(int))
    fig, (ax_map, ax_fit) = plt.subplots(1, 2, figsize=(11, 5))
    shade = LightSource(azdeg=315, altdeg=40).shade(np.asarray(e), cmap=plt.cm.gist_earth, blend_mode="soft",
                                                    vert_exag=30)
    ax_map.imshow(shade, origin="lower")
    ax_map.set_title("midpoint H = 0.8, eroded (preset land)")
    ax_map.set_axis_off()
    for name, surface, colour in (("generated", z, "tab:blue"), ("eroded", e, "tab:red")):
        a = ft.analyze(surface)
        g = variogram(np.asarray(surface, dtype=np.float64), lags)
        ax_fit.loglog(lags, g, "o", color=colour, ms=4, label=f"{name}: numpy variogram")
        band = (lags >= a["band_lo"]) & (lags <= a["band_hi"])
        c = np.mean(np.log(g[band]) - 2 * a["hurst"] * np.log(lags[band]))
        fit = lags[band]
        ax_fit.loglog(fit, np.exp(c) * fit ** (2 * a["hurst"]), "-", color=colour, lw=2,
                      label=f"{name}: H = {a['hurst']:.3f} +- {a['std_error']:.3f} (D = {a['dimension']:.3f})")
        print(f"{name}: H {a['hurst']:.4f} D {a['dimension']:.4f} estimator {a['estimator']} "
              f"band {a['band_lo']:g}..{a['band_hi']:g}; Hack h {a['drainage']['hack_h']:.3f}, "
              f"concavity {a['drainage']['theta']:.3f}")
    ax_fit.set_xlabel("lag (samples)")
    ax_fit.set_ylabel("variogram (world units^2)")
    ax_fit.set_title("variogram and the library's H fit")
    ax_fit.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "python-measure.png")
