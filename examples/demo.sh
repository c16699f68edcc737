#!/usr/bin/env bash
# The fracterra demo, end to end: a Voss midpoint terrain (16-bit heightmap
# and shaded relief), its coastline, a lightning bolt striking its highest
# peak, all rendered by POV-Ray; a fractal rock from a cube (OpenSubdiv); and
# a .blend built by headless Blender with the add-on. Outputs go to
# ${1:-demo-out}/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-demo-out}" && cd "${1:-demo-out}" && pwd)"
"$root/scripts/install-deps.sh" demo
"$root/scripts/build.sh"
ft="$root/build/native/fracterra"
step() { printf '\n== %s\n' "$*"; }

step "terrain: Voss midpoint displacement, 1025^2, H = 0.8"
"$ft" terrain --method midpoint --levels 10 --hurst 0.8 --sigma 1 --seed 7 --world-size 10 \
  --out "$out/terrain.png" --stats | tee "$out/terrain-stats.json"
"$ft" relief --in "$out/terrain.png" --out "$out/terrain-relief.png"

step "coastline at the 45% quantile, in world units"
"$ft" coastline --in "$out/terrain.png" --level q0.45 --world --out "$out/coast.csv"

step "lightning: a 3D fractal polyline with branches, striking the highest peak"
# The peak's grid position from --stats, turned into world units.
read -r px py pz < <(python3 -c '
import json, sys
s = json.load(open(sys.argv[1])); p = s["peak"]; k = s["world_size"] / (s["width"] - 1)
print(p["column"] * k, p["row"] * k, p["height"])' "$out/terrain-stats.json")
top="$(python3 -c "print(f'{$px + 1.2},{$py - 0.8},{$pz + 5.0}')")"
"$ft" polyline --method fpl3d --base "$top;$px,$py,$pz" --spread 0.12 --depth 9 \
  --branch-prob 0.015 --radius 0.035 --seed 11 --out "$out/bolt.csv" --stats

step "POV-Ray: height_field + coastline sweeps + lightning, rendered"
"$ft" scene --terrain "$out/terrain.png" --vertical-scale 1 --sea-fraction 0.45 \
  --polyline "$out/coast.csv" --kind coastline --polyline "$out/bolt.csv" --kind lightning \
  --pov "$out/scene.pov" --render "$out/scene.png" --width 800 --height 600

step "OpenSubdiv: a fractal rock from a cube"
"$ft" fractalize --in "$root/examples/meshes/cube.obj" --levels 6 --hurst 0.75 --sigma 0.25 \
  --seed 7 --out "$out/rock.obj"

step "Blender: the add-on builds a terrain scene headless and saves a .blend"
blender -b --factory-startup --python "$root/examples/20_blender_scene.py" -- \
  --out "$out/blender" --library "$root/build/native/libfracterra.so"

printf '\ndemo: wrote to %s\n' "$out"
ls -1 "$out" "$out/blender"
