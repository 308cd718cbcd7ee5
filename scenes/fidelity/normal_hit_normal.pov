// povml fidelity scene: normal_hit_normal
// Rule: the slope and aoi patterns read the intersection's perturbed normal: as a normal's
//       pattern they see the raw normal (turned toward the ray), as a pigment's they see the
//       normal the texture's normal bent (Perturb_Normal stores it before Compute_Pigment,
//       trace.cpp). A slope pigment on a bumpy sphere, an aoi pigment on a rippled floor, a
//       slope normal on the box (which bends nothing: its four samples see the same normal);
//       waves as a normal_map's pattern, with its frequency and phase, on the small sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { aoi color_map { [0 rgb <0.9, 0.8, 0.3>] [1 rgb <0.2, 0.3, 0.9>] } }
        normal { ripples 1.5 scale 0.5 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { slope y color_map { [0 rgb <0.2, 0.2, 0.8>] [0.5 rgb <0.9, 0.3, 0.2>] [1 rgb 1] } }
         normal { bumps 1 scale 0.2 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { slope <1, 1, 0> 2 } finish { specular 0.6 roughness 0.02 } }
sphere { <0.2, 0.35, -1.4>, 0.35 pigment { rgb <0.8, 0.8, 0.2> }
         normal { waves frequency 2 phase 0.3 normal_map { [0 gradient x 1 scale 0.05] [1 quilted 1 scale 0.08] } scale 0.3 }
         finish { phong 0.6 } }
