// povml fidelity scene: normal_bump_size
// Rule: the bump size (the number after the pattern, or bump_size, 0.5 by default) scales the
//       bend: the finite difference by −5·bump_size, a normal's own function by bump_size
//       (normal.cpp). Left to right on the floor: bump sizes 0.2, the default, 2 and −1; the
//       sphere's bump_size overrides the number after the pattern; on the box, an entry of a
//       normal_map uses its own size and the outer one is ignored.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
#declare F = finish { phong 0.4 }
box { <-4, -1, -2>, <-2, 0, 4> pigment { rgb 0.8 } normal { gradient z 0.2 triangle_wave scale 0.4 } finish { F } }
box { <-2, -1, -2>, <0, 0, 4> pigment { rgb 0.8 } normal { gradient z triangle_wave scale 0.4 } finish { F } }
box { <0, -1, -2>, <2, 0, 4> pigment { rgb 0.8 } normal { gradient z 2 triangle_wave scale 0.4 } finish { F } }
box { <2, -1, -2>, <4, 0, 4> pigment { rgb 0.8 } normal { gradient z -1 triangle_wave scale 0.4 } finish { F } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { quilted 0.1 bump_size 1.5 scale 0.25 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { gradient x 5 normal_map { [0 gradient y 2 scale 0.1] [1 quilted 0.3 scale 0.2] } bump_size 9 scale 2 }
      finish { specular 0.6 roughness 0.02 } }
