// povml fidelity scene: poly_shapesq
// Rule: shapesq.inc's polys, as written there (POV-Ray's term order, orders 3 to 6: Glob_5 is an
//       order 5 poly, Twin_Glob order 6, the others quartics and cubics), each clipped to a ball
//       where it is unbounded; their normals by normal1 (orders ≤ 4) and normal0 (above).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"
camera { location <0, 4, -9> look_at <0, 0.6, 0> right x*image_width/image_height angle 50 }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-5, 9, -6>, rgb 1 }
light_source { <6, 4, -3>, rgb 0.4 }
plane { y, -0.6 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
#declare F = finish { phong 0.5 }
object { Glob_5 sturm clipped_by { sphere { 0, 1.6 } } scale 0.9 rotate y*30 translate <-3, 0.4, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
object { Twin_Glob scale 0.9 rotate z*90 translate <-1.2, 0.5, 1.2> pigment { rgb <0.3, 0.8, 0.4> } finish { F } }
object { Piriform scale 0.9 rotate z*90 translate <0.4, -0.55, 1> pigment { rgb <0.9, 0.8, 0.3> } finish { F } }
object { Steiner_Surface sturm clipped_by { sphere { 0, 1.2 } } scale 0.9 translate <2.4, 0.6, 1> pigment { rgb <0.3, 0.5, 0.9> } finish { F } }
object { Quartic_Loop_1 sturm clipped_by { sphere { 0, 1 } } scale 0.7 rotate <-20, 30, 0> translate <-2.2, 0.6, -1.6> pigment { rgb <0.8, 0.5, 0.9> } }
object { Witch_Hat clipped_by { sphere { 0, 1.2 } } scale 0.5 translate <0, 0.6, -1.8> pigment { rgb <0.9, 0.6, 0.3> } }
object { Monkey_Saddle clipped_by { sphere { 0, 1 } } scale 0.6 rotate x*-90 translate <2.2, 0.6, -1.5> pigment { rgb <0.6, 0.9, 0.9> } finish { F } }
object { Cubic_Saddle_1 clipped_by { sphere { 0, 0.9 } } scale 0.6 rotate x*-90 translate <0.9, 1.9, 2.5> pigment { rgb <0.9, 0.9, 0.9> } }
