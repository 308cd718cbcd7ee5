// povml fidelity scene: hard_shadow
// Rule: shadow ray from P toward the light; an opaque object hit with 1e-3 < t < dist - 1e-3
//       blocks the light completely (OPAQUE flag) (docs/povray-rules.md §4, §2.1).
// A sphere floating above the floor casts a sharp shadow on the floor and on a second,
// smaller sphere below-right of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-3, 7, -2>, rgb 1 }
sphere { <-0.6, 1.8, 0>, 0.7 pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.5 } }
sphere { < 0.7, 0.45, 1.2>, 0.4 pigment { rgb <0.3, 0.8, 0.4> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
