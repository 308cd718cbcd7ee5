// povml fidelity scene: quadrics_cone_pointed
// Rule: a cone with r1 = 0 (the ends swapped internally, dist = 0, the base cap a point) and cones
//       with equal radii, which are cylinders (docs/povray-rules.md §15.3, §20 item 8); closed and open.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.8, 3, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.3 }
cone { <-1.3, 1.8, 0>, 0, <-1.3, 0, 0>, 0.7 pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.6 } }
cone { <0.2, 0, 0.3>, 0.5, <0.2, 1.2, 0.3>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.6 } }
cone { <1.4, 0.4, -0.8>, 0.35, <1.9, 1.6, 0.4>, 0.35 open pigment { rgb <0.4, 0.5, 0.9> } }
cone { <-0.2, 0.2, -1.5>, 0.2, <0.8, 0.2, -1.8>, 0 pigment { rgb <0.9, 0.3, 0.4> } finish { specular 0.5 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
