#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fracterra demo, end to end: a Voss midpoint terrain (16-bit heightmap
# and shaded relief), its coastline, a lightning bolt striking its highest
# peak, all rendered by POV-Ray; an eroded archipelago, its maps, rivers and
# lakes (POV-Ray); a fractal rock from a cube (OpenSubdiv); and a .blend built
# by headless Blender with the add-on. Outputs go to ${1:-demo-out}/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-demo-out}" && cd "${1:-demo-out}" && pwd)"
"$root/scripts/install-deps.sh" demo
"$root/scripts/build.sh"
ft="$root/build/native/fracterra"
step() { printf '\n== %s\n' "$*"; }

step "terrain: Voss midpoint displacement from 5 x 5 reference points (an island), 1025^2, H = 0.75"
"$ft" terrain --method midpoint --levels 10 --hurst 0.75 --sigma 2.2 --seed 9 --world-size 10 \
  --reference "$root/examples/island_reference.pgm" --out "$out/terrain.png" --stats | tee "$out/terrain-stats.json"
"$ft" relief --in "$out/terrain.png" --out "$out/terrain-relief.png"

step "coastline at the 60% quantile (the sea level), in world units"
"$ft" coastline --in "$out/terrain.png" --level q0.6 --world --out "$out/coast.csv" \
  --preview "$out/coast-preview.png"

step "lightning: a 3D fractal polyline with branches, striking the highest peak"
vscale=0.35  # the scene's vertical scale: heights are samples times this
# The peak's grid position from --stats, turned into world units.
read -r px py pz < <(python3 -c '
import json, sys
s = json.load(open(sys.argv[1])); p = s["peak"]; k = s["world_size"] / (s["width"] - 1)
print(p["column"] * k, p["row"] * k, p["height"] * float(sys.argv[2]))' "$out/terrain-stats.json" "$vscale")
top="$(python3 -c "print(f'{$px + 1.5},{$py - 1.0},{$pz + 5.0}')")"
"$ft" polyline --method fpl3d --base "$top;$px,$py,$pz" --spread 0.2 --depth 9 \
  --branch-prob 0.01 --radius 0.03 --seed 11 --out "$out/bolt.csv" --stats

step "POV-Ray: height_field + coastline sweeps + lightning, rendered"
"$ft" scene --terrain "$out/terrain.png" --vertical-scale "$vscale" --sea-fraction 0.6 \
  --polyline "$out/coast.csv" --kind coastline --polyline "$out/bolt.csv" --kind lightning \
  --radius-from-file --pov "$out/scene.pov" --render "$out/scene.png" --width 800 --height 600

step "the Mandelbrot set as a terrain (seed 002) and its curves of equal escape time"
"$ft" terrain --method mandelbrot --size 513x385 --center -0.65,0 --zoom 0.85 --iterations 40 --sigma 2 \
  --out "$out/mandelbrot.png" --curves 2,3,4,6,8 --curves-out "$out/mandelbrot-curves.csv" --stats
"$ft" relief --in "$out/mandelbrot.png" --out "$out/mandelbrot-relief.png"

step "erosion: an fBm archipelago (513^2, 30% sea) eroded by the land preset (Rugged Mountains), with its maps"
"$ft" terrain --method fbm --size 513 --hurst 0.8 --seed 7 --world-size 10 --sea fraction --sea-fraction 0.3 \
  --out "$out/uneroded.png"
# The sea is the erosion's base level: rivers end there and its floor stays.
# Without the preset's uplift: the eroded/deposited maps are height
# differences, so uplift would show as deposit everywhere (docs/erosion.md).
"$ft" erode --in "$out/uneroded.png" --preset land --uplift 0 --sea fraction --sea-fraction 0.3 \
  --out "$out/eroded.png" --maps "$out/erosion-maps"
# Water below 0.1% of the relief: the flat sea, not the lowlands.
"$ft" relief --in "$out/uneroded.png" --sea-fraction 0.001 --out "$out/uneroded-relief.png"
"$ft" relief --in "$out/eroded.png" --sea-fraction 0.001 --out "$out/eroded-relief.png"

step "rivers and lakes of the eroded archipelago, rendered by POV-Ray"
"$ft" rivers --in "$out/eroded.png" --sea fraction --sea-fraction 0.3 --min-area 0.02 --width-coefficient 0.05 \
  --depth-coefficient 0.01 --out "$out/rivers.json" --stats
"$ft" scene --terrain "$out/eroded.png" --vertical-scale 0.12 --sea-fraction 0.3 --rivers "$out/rivers.json" \
  --camera-elevation-deg 55 --camera-distance-scale 0.6 --pov "$out/rivers.pov" --render "$out/rivers.png" \
  --width 800 --height 600

step "OpenSubdiv: a fractal rock from a cube"
"$ft" fractalize --in "$root/examples/meshes/cube.obj" --levels 6 --hurst 0.75 --sigma 0.25 \
  --seed 7 --out "$out/rock.obj"

step "Blender: the add-on builds a terrain scene headless and saves a .blend"
blender -b --factory-startup --python "$root/examples/20_blender_scene.py" -- \
  --out "$out/blender" --library "$root/build/native/libfracterra.so"

printf '\ndemo: wrote to %s\n' "$out"
ls -1 "$out" "$out/blender"
