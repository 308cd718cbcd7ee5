// povml fidelity scene: sor_csg
// Rule: Sor::Inside (r² at most the segment's radius² at that height) in difference and intersection, an inverse sor, an open sor in CSG
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.8, 0.8> }
  sor { 6, <0,-0.2>, <0.6,0>, <0.3,0.7>, <0.7,1.4>, <0.5,2>, <0.5,2.2> }
  pigment { rgb <1,0.4,0.2> } translate <-1.5, 0, 0> }
intersection {
  sor { 7, <0,0>, <0.6,0>, <1,0.5>, <0.5,1>, <0.8,1.5>, <0.4,2>, <0,2.5> }
  box { <-2, 0.3, -2>, <0.3, 3, 2> }
  pigment { rgb <0.3,0.5,1> } translate <1.3, 0, 0> }
intersection { sphere { <0, 0.5, 0>, 0.6 } sor { 4, <0,-0.1>, <0.3,0>, <0.3,1>, <0,1.1> inverse } pigment { rgb <0.9,0.9,0.3> } translate <0, 0, -1.8> }
