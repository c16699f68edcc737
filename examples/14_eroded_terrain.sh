#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# An fBm terrain before and after erosion (the "land" preset: fluvial,
# hydraulic, thermal), its maps, and POV-Ray renders of both; the eroded one
# is textured by the maps (sediment where the hydraulic pass deposited,
# wet channels where the drainage area is large) through FT_Terrain_Masked:
#   bash examples/14_eroded_terrain.sh OUT_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-eroded-out}" && cd "${1:-eroded-out}" && pwd)"
ft="${FRACTERRA:-$root/build/native/fracterra}"
size="${SIZE:-513}"
"$ft" terrain --method fbm --size "$size" --hurst 0.8 --seed 7 --world-size 10 --out "$out/terrain.png"
# Without the preset's uplift: the eroded and deposited maps are height
# differences, so uplift would count as deposit everywhere and sand the
# whole terrain; the edges, held at the base level, would stand as walls.
"$ft" erode --in "$out/terrain.png" --preset land --uplift 0 --out "$out/eroded.png" --maps "$out/maps" --stats \
  > "$out/erode.json"
"$ft" analyze "$out/eroded.png" --drainage > "$out/analysis.json"
range() {  # min max of a heightfield PNG, from the JSON fracterra wrote
  python3 -c "import json, sys; d = json.load(open(sys.argv[1])); print(d[sys.argv[2]], d[sys.argv[3]])" "$@"
}
read -r zmin0 zmax0 < <(range "$out/erode.json" input_min input_max)
read -r zmin zmax < <(range "$out/erode.json" min max)
scene() {  # scene FILE.png ZMIN ZMAX TEXTURE
  cat <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare FT_Texture_Scale = 0.05;
#include "ft_terrain.inc"
#declare Sea = $2 + ${SEA:-0.25} * ($3 - $2);
#declare Wet_Tex = texture { pigment { rgb <0.16, 0.22, 0.30> } finish { diffuse 0.6 specular 0.4 roughness 0.01 } }
object { FT_Terrain("$1", <10, 10>, $2, $3, Sea) $4 }
plane { y, Sea texture { FT_Sea_Tex } }
light_source { <-600, 500, -400> color rgb <1.25, 1.2, 1.1> parallel point_at <5, 0, 5> }
light_source { <600, 1000, 400> color rgb <0.18, 0.2, 0.26> parallel point_at <5, 0, 5> shadowless }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.80, 0.86, 0.95>] [1 rgb <0.18, 0.34, 0.72>] } } }
camera { location <-2.5, 7, -6> look_at <5, 0, 5> angle 50 right x*image_width/image_height }
POV
}
scene "$out/terrain.png" "$zmin0" "$zmax0" "FT_Terrain_Texture($zmin0, $zmax0, Sea)" > "$out/before.pov"
SEA=0.04 scene "$out/eroded.png" "$zmin" "$zmax" "FT_Terrain_Masked(
  FT_Terrain_Masked(FT_Terrain_Texture($zmin, $zmax, Sea), Wet_Tex, \"$out/maps/drainage_area.png\", <10, 10>, 0.6, 0.76),
  FT_Sand_Tex, \"$out/maps/deposited.png\", <10, 10>, 0.04, 0.15)" > "$out/after.pov"
for s in before after; do
  povray +L"$root/povray_macros" +I"$out/$s.pov" +O"$out/$s.png" +W"${WIDTH:-800}" +H"${HEIGHT:-600}" \
    +A0.3 -D -V >/dev/null 2>&1
done
FRACTERRA_LIBRARY="${FRACTERRA_LIBRARY:-$(dirname "$ft")/libfracterra.so}" python3 "$root/examples/maps_montage.py" "$out/maps" "$out/maps.png" >/dev/null
echo "wrote $out/before.png $out/after.png, maps in $out/maps (side by side: $out/maps.png), drainage statistics in $out/analysis.json"
