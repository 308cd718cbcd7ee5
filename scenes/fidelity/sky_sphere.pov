// povml fidelity scene: sky_sphere
// Rule: a ray that misses everything returns the sky_sphere colour (an opaque plain pigment hides
//       the background completely: col += background.rgb * fil with fil = 0) (docs/povray-rules.md §18.1, §8.4).
// The background is set to pure red on purpose: no red may appear anywhere. The mirror ball
// reflects the sky colour.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.0, -5> look_at <0, 1.2, 0> right x*image_width/image_height }
background { rgb <1, 0, 0> }
sky_sphere { pigment { rgb <0.35, 0.55, 0.9> } }
light_source { <-3, 6, -5>, rgb 1 }
sphere { <0, 1.2, 0>, 1.0 pigment { rgb 0.1 } finish { reflection 0.8 } }
sphere { <2.2, 0.6, 0.5>, 0.5 pigment { rgb <0.9, 0.8, 0.2> } }
plane { y, 0 pigment { rgb <0.4, 0.7, 0.3> } }
