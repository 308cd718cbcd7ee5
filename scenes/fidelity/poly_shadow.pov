// povml fidelity scene: poly_shadow
// Rule: a poly is unbounded (POV-Ray's BOUND_HUGE box), so every shadow ray tests it;
//       a shadow ray leaving a poly's surface drops its root at 0 (DEPTH_TOLERANCE in poly space,
//       and Solve_Polynomial's root elimination).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
#declare R2 = 0.49; #declare r2 = 0.0625; #declare K = R2 - r2;
#declare Torus4 = quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0, 1, 0, 2*K - 4*R2, 0, K*K> }
#declare Sextic = poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1> }
#declare Ball2 = poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }
#declare Monkey = cubic { <1, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0> }
#declare Quint = poly { 5, <0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1> }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
// shadows: every shadow ray tests every poly (they are unbounded); the floor and the polys
// themselves receive them, and a light low on the right casts long shadows
light_source { <6, 1.5, -1>, rgb 0.5 }
object { Torus4 rotate x*-70 translate <-1.4, 0.9, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.5 } }
object { Sextic scale <0.4, 0.6, 0.4> rotate y*30 translate <0.2, 0.6, 0.3> pigment { rgb <0.3, 0.5, 0.9> } }
object { Ball2 scale 0.45 translate <1.4, 0.45, -0.6> pigment { rgb <0.9, 0.3, 0.2> } }
object { Quint scale 0.35 translate <-0.4, 1.6, -0.8> pigment { rgb <0.9, 0.8, 0.3> } }
object { Monkey clipped_by { sphere { 0, 1 } } scale 0.5 rotate x*-90 translate <2.2, 1.2, 0.8>
  pigment { rgb <0.8, 0.5, 0.9> } }
