// povml fidelity scene: quadrics_glass_cylinder
// Rule: refraction through a glass cylinder's caps and side (docs/povray-rules.md §6, §15.2): each crossing
//       flips the ray in or out of the interior; a glass cone beside it; filtered shadows (§4).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
cylinder { <-0.8, 0.01, 0>, <-0.8, 1.5, 0>, 0.6 pigment { rgbf <0.95, 0.95, 1, 0.9> } finish { phong 0.8 reflection 0.05 } interior { ior 1.5 } }
cylinder { <0.5, 0.5, 0.4>, <1.9, 0.9, -0.2>, 0.45 pigment { rgbt <1, 0.9, 0.9, 0.85> } finish { specular 0.6 } interior { ior 1.33 } }
cone { <0.6, 0.01, -1.2>, 0.4, <0.6, 0.9, -1.2>, 0.1 pigment { rgbf <0.8, 1, 0.8, 0.8> } interior { ior 1.6 } }
box { <-3, 0, 1.5>, <3, 2.5, 1.6> pigment { rgb <0.9, 0.3, 0.2> } }
box { <-0.2, 0, 0.7>, <0.1, 1.8, 1.0> pigment { rgb <0.2, 0.3, 0.9> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
