// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra example 10: a lightning bolt from the pure-SDL FPL macro.
// Render: povray +L../povray_macros +W640 +H480 +A0.3 10_pov_fpl_lightning.pov
// Uses FT_FPL (ft_fpl.inc), FT_Sweep and FT_Sweep_Taper (ft_sweep.inc).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "ft_fpl.inc"
#include "ft_sweep.inc"

#declare Bolt_Seed = seed(2024);
// The main bolt falls from the cloud to the ground in the xy plane (Axis z):
// uniform spread 0.1 is the "monotone, lightning-like" regime of the FPL.
#declare Bolt = FT_FPL(<0, 10, 0>, <1.8, 0, 0>, z, 0.1, false, 0, 8, Bolt_Seed);
#declare N = dimension_size(Bolt, 1);
#declare Bolt_Tex = texture { pigment { rgb <0.85, 0.88, 1.0> } finish { emission 3 diffuse 0 } }
object { FT_Sweep(Bolt, FT_Sweep_Taper(N, 0.06, 0.02), 32) texture { Bolt_Tex } no_shadow }

// Two branches leave the bolt a third and a half of the way down.
#declare I = 0;
#while (I < 2)
   #declare Start = Bolt[int(N*(0.33 + 0.17*I))];
   #declare End = Start + <2.2 - 4.4*I, -3 - 1.5*I, 0.5>;
   #declare Branch = FT_FPL(Start, End, z, 0.14, false, 0, 6, Bolt_Seed);
   object { FT_Sweep(Branch, FT_Sweep_Taper(dimension_size(Branch, 1), 0.03, 0.008), 32)
            texture { Bolt_Tex } no_shadow }
   #declare I = I + 1;
#end

light_source { <1.8, 0.3, 0> color rgb <0.8, 0.85, 1.2>*3 fade_distance 1.5 fade_power 2 }
light_source { <-30, 40, -40> color rgb <0.12, 0.13, 0.18> }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.22, 0.23, 0.30>] [1 rgb <0.03, 0.04, 0.08>] } } }
plane { y, 0 pigment { rgb <0.25, 0.27, 0.22> } finish { diffuse 0.8 } }
camera { location <0, 5, -14> look_at <0.4, 4.6, 0> angle 55 right x*image_width/image_height }
