# SPDX-License-Identifier: GPL-3.0-or-later
"""A before/after picture of one window of two erosion maps runs, for the docs:
the drainage area (log scale, as `fracterra erode --maps` writes it) above the
splat colour map (`fracterra splat --color`), before on the left, after on the
right, each panel scaled to WIDTH pixels.

    /usr/bin/python3 scripts/maps_crop.py BEFORE_DIR AFTER_DIR OUT.png X0 Y0 X1 Y1 [WIDTH]

BEFORE_DIR and AFTER_DIR each hold `maps/` (the maps folder) and `color.png`.
Needs PIL (Debian's python3-pil).
"""

import sys
from pathlib import Path

from PIL import Image


def panels(run, box, width):
    """The area (grey, stretched over the whole map's range) and the colours
    of the window `box` of one run, each `width` pixels wide."""
    area = Image.open(Path(run) / "maps" / "drainage_area.png")  # 16-bit, log10 over its range
    grey = area.point(lambda v: v / 256).convert("L")
    colour = Image.open(Path(run) / "color.png").convert("RGB")
    height = round(width * (box[3] - box[1]) / (box[2] - box[0]))
    return [im.crop(box).resize((width, height), Image.NEAREST) for im in (grey.convert("RGB"), colour)]


def main():
    before, after, out = sys.argv[1:4]
    box = tuple(int(v) for v in sys.argv[4:8])
    width = int(sys.argv[8]) if len(sys.argv) > 8 else 480
    left, right = panels(before, box, width), panels(after, box, width)
    gap = 6
    h = left[0].height
    sheet = Image.new("RGB", (2 * width + gap, 2 * h + gap), "white")
    for column, (area, colour) in enumerate((left, right)):
        sheet.paste(area, (column * (width + gap), 0))
        sheet.paste(colour, (column * (width + gap), h + gap))
    sheet.save(out, optimize=True)
    print(f"wrote {out}")


main()
