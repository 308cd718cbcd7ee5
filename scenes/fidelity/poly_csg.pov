// povml fidelity scene: poly_csg
// Rule: a poly's Inside is its value below INSIDE_TOLERANCE (1e-4) in poly space, and
//       inverse toggles its inverted flag (Poly::Invert), so difference, intersection, inverse and
//       merge keep each member's hits by that test.
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
// a box with the quartic torus taken away (the torus's Inside: its value below 1e-4)
difference {
  box { <-0.9, 0, -0.9>, <0.9, 0.5, 0.9> }
  object { Torus4 translate y*0.5 pigment { rgb <0.9, 0.9, 0.3> } }
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.5 }
  rotate y*20 translate <-2.2, 0, 0.6> }
// the rounded cube (order 6) cut by an order 2 ball: intersection
intersection {
  object { Sextic scale 0.5 }
  object { Ball2 scale 0.62 pigment { rgb <0.9, 0.2, 0.2> } }
  pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.4 }
  rotate <20, 30, 0> translate <-0.5, 0.7, -0.3> }
// a ball with the rounded cube hollowed out by inverse, cut open by a box
intersection {
  object { Ball2 scale 0.55 }
  object { Sextic scale 0.42 inverse pigment { rgb <0.2, 0.4, 0.9> } }
  box { <-1, -1, -1>, <1, 1, 0> inverse }
  pigment { rgb <0.4, 0.7, 0.9> }
  rotate y*-30 translate <0.9, 0.6, 0> }
// a quartic torus inverted alone inside a merge with an order 5 poly
merge {
  object { Quint scale 0.4 }
  object { Torus4 scale 0.7 rotate x*90 }
  pigment { rgb <0.8, 0.5, 0.9> } finish { phong 0.3 }
  translate <2.3, 0.6, 0.6> }
