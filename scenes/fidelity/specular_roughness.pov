// povml fidelity scene: specular_roughness
// Rule: Blinn specular = specular * (H.N/|H|)^(1/roughness) * lc, H = (-D + L)/2;
//       roughness is stored as its reciprocal, default 0.05 (docs/povray-rules.md §3.3, §10.1).
// Left to right: specular 0.8 with roughness 0.3, default (0.05), 0.003.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.08, 0.08, 0.1> }
light_source { <3, 5, -6>, rgb 1 }
sphere { <-2.2, 0.8, 0>, 0.9 pigment { rgb <0.7, 0.25, 0.2> } finish { specular 0.8 roughness 0.3 } }
sphere { <0, 0.8, 0>, 0.9 pigment { rgb <0.7, 0.25, 0.2> } finish { specular 0.8 } }
sphere { <2.2, 0.8, 0>, 0.9 pigment { rgb <0.7, 0.25, 0.2> } finish { specular 0.8 roughness 0.003 } }
plane { y, -0.3 pigment { rgb 0.45 } finish { specular 0.3 roughness 0.1 } }
