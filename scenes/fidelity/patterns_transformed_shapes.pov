// povml fidelity scene: patterns_transformed_shapes
// Rule: patterns on an ellipsoid and on a scaled plane are evaluated at the world hit point through
//       the composed inverse transform; frequency on checker and brick re-enables the value wrap
//       (docs/povray-rules.md §14.7, §17.1).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <2, 8, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 scale 0.7 } scale <1, 1, 2> rotate x*0 }
sphere { 0, 1 pigment { gradient x color_map { [0 rgb <1,0,0>] [0.5 rgb <0,1,0>] [1 rgb <0,0,1>] } frequency 3 } scale <1.5, 0.8, 1> rotate z*30 translate y*1.2 }
sphere { <2,1,0>, 0.5 pigment { checker rgb 1 frequency 2 phase 0.3 } }
sphere { <-2,1,0>, 0.5 pigment { brick frequency 1.5 scale 0.1 } }
