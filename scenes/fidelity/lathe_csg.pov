// povml fidelity scene: lathe_csg
// Rule: Lathe::Inside (the crossings towards growing radius at the point's height) in intersection and difference, an inverse lathe
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 7, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
intersection {
  lathe { cubic_spline 7, <0,-0.5>, <0,0>, <0.8,0.2>, <0.3,1>, <0.7, 1.6>, <0, 2>, <0, 2.5> }
  box { <-2, 0.5, -2>, <0.2, 3, 2> }
  pigment { rgb <0.3,0.5,1> } translate <-1.6, 0, 0> }
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.5, 0.8> }
  lathe { linear_spline 4, <0,0>, <0.6,0.3>, <0.5,1.8>, <0,1.8> }
  pigment { rgb <1,0.4,0.2> } translate <1.4, 0, 0> }
intersection { sphere { <0, 0.5, 0>, 0.6 } lathe { linear_spline 3, <0,0>, <0.3,0.5>, <0,1> inverse } pigment { rgb <0.9,0.9,0.3> } translate <0, 0, -1.8> }
