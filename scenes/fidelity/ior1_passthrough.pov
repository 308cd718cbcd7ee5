// povml fidelity scene: ior1_passthrough
// Rule: with |ior - 1| < EPSILON a transmitted ray continues straight and is a "continued" ray:
//       the trace level is NOT incremented (docs/povray-rules.md §6.2, §7, pitfall §13.10).
// max_trace_level is 2, yet the background and the far balls stay visible through a chain of
// three rgbt/rgbf balls (6 surface crossings) and through a transparent ball nested inside
// another transparent ball.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 2 }
camera { location <-1.5, 1.2, -6> look_at <-0.2, 1.0, 0> right x*image_width/image_height }
background { rgb <0.9, 0.8, 0.4> }
light_source { <-3, 6, -5>, rgb 1 }
// chain along the view direction
sphere { <-1.2, 1.1, -3.0>, 0.6 pigment { rgbt <1, 0.8, 0.8, 0.8> } }
sphere { <-0.9, 1.1, -1.0>, 0.6 pigment { rgbf <0.8, 1, 0.8, 0.8> } }
sphere { <-0.6, 1.1,  1.0>, 0.6 pigment { rgbt <0.8, 0.8, 1, 0.7> } }
sphere { <-0.2, 1.1,  4.0>, 0.6 pigment { rgb <0.9, 0.2, 0.5> } }
// nested pair
sphere { < 1.8, 1.2, 0>, 1.0 pigment { rgbt <0.7, 0.9, 1, 0.85> } }
sphere { < 1.8, 1.2, 0>, 0.4 pigment { rgbt <1, 0.4, 0.2, 0.5> } }
plane { y, -0.5 pigment { rgb <0.3, 0.5, 0.3> } }
