#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Horton's ratios of fracterra's river network against GRASS GIS's
r.stream.extract on the same eroded heights (issue 40), computed from GRASS's
rasters independently of the library by scripts/grass_stream_orders.py:
the island (`--falloff radial --edge-level -0.6`) and that island in a 30%
sea, seed 1, fBm 513^2, Rugged Mountains, min_area 0.1 (about 3 s each).

Usage: grass_stream_orders_test.py FRACTERRA_CLI    (exit 77: GRASS is not installed)

Measured (2026-12-03, GRASS 8.2.1) on 7 terrains (plain seed 1,
island and island in a sea seeds 1-3; docs/rivers.md): our R_b less GRASS's
0.56, 0.90, 0.67, 0.52, 0.29, 0.42, -0.06 (mean 0.47, s 0.31; ours keeps
fewer streams of the orders above 3), R_l's difference -0.22..0.18. Checked:
|R_b ours - GRASS| <= 1.1 (mean + 2 s) and |R_l ours - GRASS| <= 0.4 (twice
the largest), and GRASS's own R_b in 3-5.4 (the real range; in a sea the
bound of tests/native/drainage_properties_test.cpp). It does not catch the
issue's walled basin (edge level 0, seed 1: 1.01, GRASS 3.99): that is a
landform, not an extraction fault.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

LINE = re.compile(r"^(\S+)\s+seed (\d+): fracterra R_b ([\d.]+) R_l ([\d.]+) .*GRASS r.stream.extract R_b ([\d.]+) "
                  r"R_l ([\d.]+)")


def main():
    if shutil.which("grass") is None:
        print("GRASS is not installed (Debian grass-core): skipped")
        sys.exit(77)
    script = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "grass_stream_orders.py")
    with tempfile.TemporaryDirectory() as work:
        out = subprocess.run([sys.executable, script, sys.argv[1], work, "island:1", "island_sea:1"],
                             capture_output=True, text=True)
    print(out.stdout, out.stderr)
    if out.returncode != 0:
        sys.exit("grass_stream_orders.py failed")
    rows = [LINE.match(line) for line in out.stdout.splitlines()]
    rows = [r for r in rows if r]
    failed = len(rows) != 2
    for r in rows:
        name, rb, rl, grb, grl = r[1], float(r[3]), float(r[4]), float(r[5]), float(r[6])
        for ok, what in ((abs(rb - grb) <= 1.1, f"R_b {rb} against GRASS's {grb}"),
                         (abs(rl - grl) <= 0.4, f"R_l {rl} against GRASS's {grl}"),
                         (3.0 <= grb <= 5.4, f"GRASS's R_b {grb} outside 3-5.4")):
            if not ok:
                print(f"FAIL {name}: {what}")
                failed = True
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
