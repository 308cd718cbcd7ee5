// povml fidelity scene: hf_csg
// Rule: CSG: Inside below the surface (water raised), difference, intersection, inverse; an intersection's box leaves the height field out
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -6> rgb 1 }
light_source { <3, 4, -2> rgb 0.4 }
#declare HF = height_field { png "../images/hf_grey8.png" translate <-0.5, 0, -0.5> scale <2, 1, 2> }
difference { box { <-0.7, -0.5, -0.7>, <0.7, 0.8, 0.7> } object { HF } translate <-1.3, 0, 0> pigment { rgb <0.9, 0.5, 0.3> } }
intersection { object { HF } sphere { <0, 0.3, 0>, 0.9 } translate <1.3, 0, 0> pigment { rgb <0.4, 0.6, 0.9> } }
intersection { box { <-0.6, -0.3, -0.6>, <0.6, 0.9, 0.6> } object { HF inverse } translate <0, 0, 1.6> pigment { rgb <0.8, 0.8, 0.4> } }
plane { y, -0.6 pigment { rgb 0.6 } }
