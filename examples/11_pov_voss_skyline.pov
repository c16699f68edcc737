// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra example 11: mountain skylines from the pure-SDL Voss profile.
// Render: povray +L../povray_macros +W640 +H480 +A0.3 11_pov_voss_skyline.pov
// Uses FT_Voss_Profile (ft_voss.inc) and FT_Sweep_Uniform (ft_sweep.inc).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "ft_voss.inc"
#include "ft_sweep.inc"

#declare Sky_Seed = seed(11);
// Three ranges, farther ones paler (aerial perspective), H = 0.8.
#declare Range = 0;
#while (Range < 3)
   #declare X = FT_Voss_Profile(9, 0.8, 4, Sky_Seed);
   #declare N = dimension_size(X, 1);
   #declare Width = 30;
   #declare Depth = 10 + 12*Range;
   #declare Base = 2 + 1.5*Range;
   // The silhouette as a prism: profile on top, closed along the bottom.
   prism {
      linear_sweep linear_spline 0, 1, N + 3,
      #declare I = 0;
      #while (I < N)
         <-Width/2 + Width*I/(N - 1), Base + X[I] - X[0]>,
         #declare I = I + 1;
      #end
      <Width/2, -1>, <-Width/2, -1>, <-Width/2, Base>
      rotate -90*x scale <1 + 0.6*Range, 1, 1> translate Depth*z
      pigment { rgb <0.16, 0.18, 0.24> + Range*<0.14, 0.15, 0.16> }
      finish { diffuse 0.3 emission 0.25 }
   }
   // The nearest ridge line drawn as a thin lit sweep.
   #if (Range = 0)
      #declare Ridge = array[N];
      #declare I = 0;
      #while (I < N)
         #declare Ridge[I] = <-Width/2 + Width*I/(N - 1), Base + X[I] - X[0], Depth - 1.05>;
         #declare I = I + 1;
      #end
      object { FT_Sweep_Uniform(Ridge, 0.03, 32) pigment { rgb <1.0, 0.7, 0.4> } finish { emission 0.8 } }
   #end
   #declare Range = Range + 1;
#end

sky_sphere { pigment { gradient y color_map { [0 rgb <1.0, 0.62, 0.36>] [0.15 rgb <0.62, 0.52, 0.62>]
                                              [0.4 rgb <0.20, 0.26, 0.48>] } } }
light_source { <-100, 30, 200> color rgb <1.0, 0.8, 0.6> }
plane { y, 0 pigment { rgb <0.10, 0.11, 0.14> } finish { diffuse 0.4 } }
camera { location <0, 1.5, -12> look_at <0, 3, 10> angle 60 right x*image_width/image_height }
