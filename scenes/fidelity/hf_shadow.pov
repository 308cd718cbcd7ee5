// povml fidelity scene: hf_shadow
// Rule: shadows: the field casts onto a plane and onto itself (shadow rays walk the blocks from the surface)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -4> look_at <0, 0, 0> angle 45 }
light_source { <-6, 2.5, -1> rgb 1 }
height_field { png "../images/hf_grey8.png" translate <-0.5, 0, -0.5> scale <2, 0.7, 2> pigment { rgb 0.9 } }
plane { y, 0.05 pigment { rgb <0.5, 0.6, 0.8> } }
sphere { <1.5, 0.4, -0.6>, 0.3 pigment { rgb <0.9, 0.2, 0.2> } }
