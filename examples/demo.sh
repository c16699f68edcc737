#!/usr/bin/env bash
# The fracterra demo: generates a terrain (16-bit heightmap + shaded-relief
# preview) into ${1:-demo-out}/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-demo-out}" && cd "${1:-demo-out}" && pwd)"
"$root/scripts/install-deps.sh" demo
"$root/scripts/build.sh"
ft="$root/build/native/fracterra"
"$ft" terrain --method midpoint --levels 10 --hurst 0.8 --seed 7 --out "$out/terrain.png" --stats
"$ft" relief --in "$out/terrain.png" --out "$out/terrain-relief.png"
echo "demo: wrote $out/terrain.png and $out/terrain-relief.png"
