# SPDX-License-Identifier: GPL-3.0-or-later
"""The library from numpy in one figure: the FPL ensemble statistics against
the paper's table (seed 003), a terrain's Hurst exponent with the variogram
it was fitted on, and an eroded terrain's rivers and lakes.

    python3 -m venv --system-site-packages venv
    venv/bin/pip install --no-index --no-build-isolation build/python/fracterra-*.whl
    venv/bin/python examples/31_python_polylines.py docs/images/python-polylines.png [--quick]

--quick (the tests run it so) uses fewer lines per spread and a smaller
terrain; the checks are the same, with tolerances for the smaller ensembles.
It exits non-zero when a statistic leaves its tolerance, so the tests fail.
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LightSource  # noqa: E402

import fracterra as ft  # noqa: E402


def fpl_table(count):
    """Ensemble means of eta / s, chi / s and gamma at depth 8 against the paper's fits
    (uniform urf(s): eta ~ 0.65 s, chi ~ 0.29 s, gamma ~ 2^(0.71 s^1.82 r))."""
    study = ft.fpl_study(rng="uniform", spreads=[0.1, 0.2, 0.3, 0.4, 0.5], depths=[8], count=count, seed=1)
    print(f"FPL, uniform generator, depth 8, {count} lines per spread:")
    print("   s   eta/s (paper 0.65)   chi/s (paper 0.29)   gamma (paper)")
    for i, s in enumerate(study["spread"]):
        print(f"{s:5.2f}   {study['eta_mean'][i] / s:6.3f} +- {2 * study['eta_se'][i] / s:.3f}"
              f"     {study['chi_mean'][i] / s:6.3f} +- {2 * study['chi_se'][i] / s:.3f}"
              f"     {study['gamma_mean'][i]:6.3f} ({study['paper_gamma'][i]:.3f})")
    return study


def check(study, h, rivers):
    """The figure's claims, with tolerances (a failed one exits non-zero):
    - eta/s and chi/s within 15 % of the paper's fitted slopes at every spread (the paper's
      fits are themselves least squares over its own ensembles; 15 % is several standard
      errors for 50 lines);
    - gamma within 10 % of 2^(0.71 s^1.82 r) for s <= 0.4 (beyond, the paper's power law
      overshoots its own points);
    - the midpoint terrain of H = 0.8 measures H within 0.1 (one realisation scatters by a
      few hundredths at 257^2);
    - the eroded terrain drains through at least 5 river segments, Strahler order >= 2."""
    s = study["spread"]
    bad = []
    for name, paper in (("eta", 0.65), ("chi", 0.29)):
        ratio = study[f"{name}_mean"] / s / paper
        if np.any(np.abs(ratio - 1) > 0.15):
            bad.append(f"{name}/s off the paper's {paper}: ratios {np.round(ratio, 3)}")
    near = s <= 0.4
    g = study["gamma_mean"][near] / study["paper_gamma"][near]
    if np.any(np.abs(g - 1) > 0.10):
        bad.append(f"gamma off the paper's fit: ratios {np.round(g, 3)}")
    if abs(h - 0.8) > 0.1:
        bad.append(f"H = {h:.3f}, not 0.8 +- 0.1")
    if rivers.segment_count < 5 or rivers.order.max() < 2:
        bad.append(f"{rivers.segment_count} river segments of order up to {rivers.order.max()}")
    return bad


def main(out, quick=False):
    study = fpl_table(50 if quick else 200)
    levels = 8 if quick else 9
    z = ft.terrain(method="midpoint", levels=levels, hurst=0.8, seed=7, world_size=10)
    a = ft.analyze(z, points=True, drainage=False)
    print(f"terrain: H {a['hurst']:.3f} +- {a['std_error']:.3f}, D {a['dimension']:.3f} ({a['estimator']})")
    built = ft.terrain(method="midpoint", levels=levels, hurst=0.8, sigma=1.5, seed=7, world_size=10,
                       sea="fraction", sea_fraction=0.25, erode="rugged_mountains", rivers=True)
    e, rivers = built.terrain, built.rivers
    m = rivers.measures()
    print(f"rivers: {rivers.segment_count} segments, {rivers.lake_count} lakes, Horton R_b "
          f"{m['bifurcation_ratio']:.2f}, drainage density {m['drainage_density']:.2f} per unit")

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8))
    ax = axes[0]
    s = study["spread"]
    for name, paper, colour in (("eta", 0.65, "tab:blue"), ("chi", 0.29, "tab:red")):
        ax.errorbar(s, study[f"{name}_mean"] / s, yerr=2 * study[f"{name}_se"] / s, fmt="o", color=colour,
                    label=f"{name} / s, measured")
        ax.axhline(paper, color=colour, ls="--", lw=1, label=f"paper {paper}")
    ax.set_xlabel("spread s")
    ax.set_ylim(0, 0.9)
    ax.set_title("FPL (uniform), depth 8: eta / s and chi / s")
    ax2 = ax.twinx()
    ax2.plot(s, study["gamma_mean"], "s", color="tab:green", label="gamma, measured")
    ax2.plot(s, study["paper_gamma"], "-", color="tab:green", lw=1, label="paper 2^(0.71 s^1.82 r)")
    ax2.set_ylabel("gamma (length / chord)")
    lines = ax.get_legend_handles_labels()
    more = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], fontsize=7, loc="upper left")

    ax = axes[1]
    x, y = a["fit"]["x"], a["fit"]["y"]
    ax.loglog(x, y, "o", ms=4, label="variogram (the points fitted)")
    c = np.mean(np.log(y) - 2 * a["hurst"] * np.log(x))
    ax.loglog(x, np.exp(c) * x ** (2 * a["hurst"]), "-", lw=2, label=f"slope 2H, H = {a['hurst']:.3f}")
    ax.set_xlabel("lag (samples)")
    ax.set_ylabel("mean squared increment")
    ax.set_title(f"midpoint terrain, H = 0.8 asked: {a['estimator']}")
    ax.legend(fontsize=8)

    ax = axes[2]
    spacing = e.world_size / (e.shape[1] - 1)
    extent = (0, e.world_size, 0, spacing * (e.shape[0] - 1))
    shade = LightSource(azdeg=315, altdeg=40).shade(np.asarray(e), cmap=plt.cm.gist_earth, blend_mode="soft",
                                                    vert_exag=2 / spacing)
    ax.imshow(shade, origin="lower", extent=extent)
    water = np.ma.masked_where(rivers.water_mask == ft.Rivers.LAND, rivers.water_mask)
    ax.imshow(water >= -2, origin="lower", extent=extent, cmap="Blues", alpha=0.6, vmin=0, vmax=1.5)
    for k, seg in enumerate(rivers.segments()):
        ax.plot(seg[:, 0], seg[:, 1], color="#1a5fb4", lw=0.4 + 0.6 * rivers.order[k])
    ax.set_title(f"eroded (rugged_mountains): {rivers.segment_count} rivers, {rivers.lake_count} lakes")
    ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    print(f"wrote {out}")
    bad = check(study, a["hurst"], rivers)
    for b in bad:
        print("FAILED:", b, file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    sys.exit(main(args[0] if args else "python-polylines.png", quick="--quick" in sys.argv))
