#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# docs/images/rivers-scene.png: an fBm terrain (513^2, H = 0.8, seed 7, 10
# world units) eroded by the valleys preset (Gentle Valleys), its rivers and
# lakes (min area 0.03) carved into it, 20% sea, rendered by POV-Ray from above
# (docs/rivers.md):
#   bash examples/16_rivers_scene.sh OUT_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-rivers-out}" && cd "${1:-rivers-out}" && pwd)"
ft="${FRACTERRA:-$root/build/native/fracterra}"
"$ft" terrain --method fbm --size "${SIZE:-513}" --hurst 0.8 --seed 7 --world-size 10 --erode valleys --out "$out/eroded.png"
"$ft" rivers --in "$out/eroded.png" --sea fraction --sea-fraction 0.2 --min-area 0.03 --width-coefficient 0.05 \
  --depth-coefficient 0.01 --carve "$out/carved.png" --out "$out/rivers.json" --stats > "$out/rivers-stats.json"
"$ft" scene --terrain "$out/carved.png" --sea-fraction 0.2 --rivers "$out/rivers.json" --camera-elevation-deg 65 \
  --camera-distance-scale 0.45 --pov "$out/rivers.pov" --render "$out/rivers.png" --width 640 --height 480
echo "wrote $out/rivers.png"
