#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every erosion preset on the add-on's default mountain (midpoint, sigma 2,
# levelling 1, height offset 1.5, radial falloff 0.9; 10 world units) on
# three seeds, as shaded reliefs, beside the uneroded terrain, at the default
# strength (docs/erosion.md; the preview and final pairs there are Blender's):
#   bash examples/15_erosion_presets.sh OUT_DIR [LEVELS]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-erosion-presets}" && cd "${1:-erosion-presets}" && pwd)"
ft="${FRACTERRA:-$root/build/native/fracterra}"
levels="${2:-8}"
mountain=(--method midpoint --sigma 2 --levelling 1 --height-offset 1.5 --falloff radial --falloff-width 0.9
          --world-size 10)
for seed in 1 2 3; do
  "$ft" terrain "${mountain[@]}" --levels "$levels" --seed "$seed" --out "$out/uneroded-seed$seed.npy"
  "$ft" relief --in "$out/uneroded-seed$seed.npy" --out "$out/uneroded-seed$seed.png" --sea-fraction 0
  # `terrain --erode` takes the pipeline's names (valleys, ...); the files are named by the preset ids.
  for pair in gentle_valleys:valleys rugged_mountains:land badlands:badlands alluvial_fans:rain scree_slopes:scree; do
    preset="${pair%%:*}"
    "$ft" terrain "${mountain[@]}" --levels "$levels" --seed "$seed" --erode "${pair##*:}" --out "$out/$preset-seed$seed.npy"
    "$ft" relief --in "$out/$preset-seed$seed.npy" --out "$out/$preset-seed$seed.png" --sea-fraction 0
  done
done
rm -f "$out"/*.npy "$out"/*.npy.json  # the heights and their sidecars: the PNGs are the pictures
