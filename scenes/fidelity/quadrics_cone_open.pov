// povml fidelity scene: quadrics_cone_open
// Rule: cone { … open } has no end caps: the inside of the funnel is visible (docs/povray-rules.md §15.3);
//       the lower nappe of the double cone is cut away by dist ≤ z.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 9, -4>, rgb 1 }
light_source { <4, 3, -5>, rgb 0.4 }
cone { <-0.9, 0.1, 0>, 0.2, <-0.9, 1.5, 0>, 0.9 open pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 } }
cone { <1.2, 0.6, 0.2>, 0.6, <1.3, 1.3, -0.6>, 0.25 open pigment { rgb <0.5, 0.8, 0.9> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
