// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra example 12: a fracterra terrain PNG with FT_Terrain, its
// materials by altitude and slope, a sea, and an FPL coastline path.
// Render: povray +L../povray_macros +W640 +H480 +A0.3 12_pov_terrain_macro.pov
// The PNG was made by: fracterra terrain --levels 7 --hurst 0.8 --seed 11 --out 12_pov_terrain.png
// Uses FT_Terrain, FT_Terrain_Texture, FT_Sea_Tex (ft_terrain.inc), FT_FPL, FT_Sweep_Uniform.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare FT_Texture_Scale = 0.005;  // material detail for a 1 x 1 terrain
#include "ft_terrain.inc"
#include "ft_fpl.inc"
#include "ft_sweep.inc"

#declare ZMin = 0;      // black pixels
#declare ZMax = 0.2;    // white pixels: relief of 20% of the width
#declare Sea = 0.12;
object {
   FT_Terrain("12_pov_terrain.png", <1, 1>, ZMin, ZMax, Sea)
   FT_Terrain_Texture(ZMin, ZMax, Sea)
}
plane { y, Sea texture { FT_Sea_Tex } }

// A fractal boat route across the sea, drawn on the water.
#declare Route = FT_FPL(<-0.3, Sea, -0.2>, <1.2, Sea, 0.1>, y, 0.22, false, 0, 7, seed(5));
object { FT_Sweep_Uniform(Route, 0.002, 32) pigment { rgb <1, 0.9, 0.3> } finish { emission 0.5 } }

light_source { <-60, 50, -40> color rgb <1.25, 1.2, 1.1> parallel point_at <0.5, 0, 0.5> }
light_source { <60, 100, 40> color rgb <0.18, 0.2, 0.26> parallel point_at <0.5, 0, 0.5> shadowless }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.80, 0.86, 0.95>] [0.2 rgb <0.45, 0.62, 0.90>]
                                              [1 rgb <0.18, 0.34, 0.72>] } } }
camera { location <-0.35, 0.75, -0.9> look_at <0.5, 0.08, 0.5> angle 45 right x*image_width/image_height }
