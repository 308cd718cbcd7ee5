// povml stiff scene: mirrors_256
// Stresses: recursion at POV-Ray's hard limit. Two parallel mirror planes 2 units apart face each
// other with reflection just below 1 and adc_bailout 0, so no ray is ever cut for its weight: a
// ray between the mirrors bounces until max_trace_level 256 (the largest value POV-Ray accepts
// without a warning, docs/povray-rules.md §7) and gets black there. There is a floor but no ceiling:
// every camera ray that rises bounces the full 256 levels (255 reflected rays, each with its
// shadow ray), the others until they reach the floor.
// A correct image: the camera looks almost straight at one mirror; the red and green balls
// repeat into a receding corridor, each copy dimmer and greener (the mirrors reflect
// <0.99, 0.995, 0.97>); above the floor the mirrors' own faint diffuse, summed over 256 bounces,
// gives a smooth haze, green because green is reflected best, not black; the light's mirror
// images merge into a glow at the vanishing point. No pixel is NaN, and the render finishes without
// exhausting the stack.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 256 adc_bailout 0 }
camera { location <0.6, 0.5, -1> look_at <-1, 0.62, -0.3> right x*image_width/image_height angle 65 }
background { rgb <0.4, 0.6, 0.9> }
light_source { <0.3, 2.5, -1>, rgb 1 }
#declare Mirror = texture { pigment { rgb <0.1, 0.15, 0.3> } finish { ambient 0.02 diffuse 0.05 reflection rgb <0.99, 0.995, 0.97> } }
plane { x, 1 texture { Mirror } }
plane { -x, 1 texture { Mirror } }
sphere { <-0.3, 0.35, 0.2>, 0.35 pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.6 } }
sphere { < 0.45, 0.25, 1.2>, 0.25 pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.6 } }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.6> } }
