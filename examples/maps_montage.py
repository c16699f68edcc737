# SPDX-License-Identifier: GPL-3.0-or-later
"""Four erosion maps side by side as one 16-bit grey PNG, for docs/erosion.md:
drainage area (log scale), slope, eroded depth and deposited sediment, each
scaled to its own range and halved in size.

    python3 examples/maps_montage.py MAPS_DIR OUT.png

MAPS_DIR is what `fracterra erode --maps` writes. Uses the add-on's ctypes
binding from this source tree (the library from build/native, or
FRACTERRA_LIBRARY).
"""

import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "blender_addon"))

from fracterra.core import raster  # noqa: E402
from fracterra.core.terrain import Heightfield  # noqa: E402

PANELS = (("drainage_area", True), ("slope", False), ("eroded", False), ("deposited", False))


def panel(path, log, scale):
    """Rows of the map at half size, scaled to 0..1 over its own range (a log
    panel of a map already written on a log scale, per maps.json, as it is)."""
    with raster.read_heightfield(path) as hf:
        w, h, values = hf.width, hf.height, hf.to_array()
    if log and scale != "log10":
        values = [math.log(max(v, 1e-12)) for v in values]
    lo, hi = min(values), max(values)
    span = (hi - lo) or 1.0
    return [[(values[y * w + x] - lo) / span for x in range(0, w, 2)] for y in range(0, h, 2)]


def main():
    maps, out = Path(sys.argv[1]), sys.argv[2]
    index = json.loads((maps / "maps.json").read_text())
    panels = [panel(maps / f"{name}.png", log, index[name].get("scale", "linear")) for name, log in PANELS]
    rows = [sum((p[y] for p in panels), []) for y in range(len(panels[0]))]
    with Heightfield.from_values(len(rows[0]), len(rows), [v for row in rows for v in row]) as hf:
        raster.write_heightfield(hf, out)
    print(f"wrote {out}")


main()
