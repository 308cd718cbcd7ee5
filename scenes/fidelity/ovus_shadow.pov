// povml fidelity scene: ovus_shadow
// Rule: shadow rays meet an ovus between the point and the light: eggs cast their shadows on
//       the floor and on each other.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-2, 8, -2>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
ovus { 0.6, 0.4 translate <-1.2, 1.4, 0> pigment { rgb <0.9, 0.3, 0.2> } }
ovus { 0.4, 0.7 rotate 30*z translate <1.2, 1.6, 0.5> pigment { rgb <0.3, 0.5, 0.9> } }
sphere { <1.5, 0.5, 0.8>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } }
