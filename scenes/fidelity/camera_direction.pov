// povml fidelity scene: camera_direction
// Rule: without look_at/angle the ray is normalize(direction + x0*right + y0*up); the length of
//       `direction` sets the zoom (|direction| 1.8 = narrower view than the default 1)
//       (docs/povray-rules.md §1.3, §1.4).
// direction <0,0,1.8> with explicit up y and right x*image_width/image_height.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> direction <0, 0, 1.8> up y right x*image_width/image_height }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <-1.5, 0.6, 0>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { < 0.0, 0.8, 0>, 0.7 pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }
sphere { < 1.5, 0.6, 0>, 0.5 pigment { rgb <0.2, 0.6, 0.9> } }
plane { y, 0 pigment { rgb 0.75 } }
