// povml fidelity scene: camera_sky
// Rule: look_at builds R = normalize(sky x D), U = D x R; a tilted `sky` rolls the view
//       (docs/povray-rules.md §1.3 step 4).
// sky <0.35,1,0>: the horizon and the row of balls appear tilted (rolled clockwise).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> sky <0.35, 1, 0> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-2.0, 0.6, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { < 0.0, 0.8, 0>, 0.7 pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }
sphere { < 2.0, 0.6, 0>, 0.5 pigment { rgb <0.2, 0.6, 0.9> } }
plane { y, 0 pigment { rgb 0.75 } }
