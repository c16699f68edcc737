#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Mandelbrot set as a terrain with its curves of equal escape time,
# rendered by POV-Ray (docs/images/mandelbrot-pov.png):
#   bash examples/13_mandelbrot.sh OUT_DIR
# The sea sits on the equipotential of escape time 1.6; the curves above it
# are the equipotentials 2 .. 8, in world units with z = their height, so
# they lie on the surface at --vertical-scale 1.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-mandelbrot-out}" && cd "${1:-mandelbrot-out}" && pwd)"
ft="${FRACTERRA:-$root/build/native/fracterra}"
"$ft" terrain --method mandelbrot --size 1025x769 --center -0.65,0 --zoom 0.85 --iterations 40 \
  --sigma 2 --world-size 10 --out "$out/mandelbrot.png" \
  --curves 2,2.5,3,4,5,6,8 --curves-out "$out/curves.csv" --curves-world --stats
# The height of escape time 1.6 at sigma 2: 2 (1 - (1 + s)^-1/2), s = log2(1 + 2^1.6).
sea=$(python3 -c 'import math; s = math.log2(1 + 2 ** 1.6); print(2 * (1 - 1 / math.sqrt(1 + s)))')
"$ft" scene --terrain "$out/mandelbrot.png" --vertical-scale 1 --water "$sea" \
  --polyline "$out/curves.csv" --kind line --radius 0.018 --elevation 32 --azimuth 190 \
  --pov "$out/scene.pov" --render "$out/scene.png" --width "${WIDTH:-800}" --height "${HEIGHT:-600}"
